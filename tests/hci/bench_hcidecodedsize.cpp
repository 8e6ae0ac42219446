// What the decoded-size walk (estimateDecodedBytes) costs before a big frame is parsed: a real list of
// 30,000 vehicles (about 2.5 MB) and a 16 MiB frame of empty DomainObjectWrappers (the expansion it
// refuses), walked and, for the real list, parsed; the best of several runs in MB/s.
//   bench_hcidecodedsize [runs]
#include "HciDecodedSize.h"
#include "Messages.pb.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace pb = com::ugcs::ucs::proto;
using Clock = std::chrono::steady_clock;

namespace {

std::string vehicleList(int count)
{
    pb::GetObjectListResponse list;
    list.set_objecttype("Vehicle");
    for (int i = 0; i < count; ++i) {
        pb::Vehicle *v = list.add_objects()->mutable_vehicle();
        v->set_id(i + 1);
        v->set_name("Survey hexacopter " + std::to_string(i + 1) + " of the northern block");
        v->set_tag("SN-" + std::to_string(100000 + i));
        v->set_tailnumber("YL-" + std::to_string(i));
    }
    return list.SerializeAsString();
}

std::string emptyWrappers(size_t count)
{
    std::string wire = "\x0a\x07Vehicle";
    for (size_t i = 0; i < count; ++i)
        wire.append("\x12\x00", 2);
    return wire;
}

template<class F>
double bestSeconds(int runs, F &&f)
{
    double best = 1e9;
    for (int r = 0; r < runs; ++r) {
        const auto start = Clock::now();
        f();
        best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
    }
    return best;
}

} // namespace

int main(int argc, char **argv)
{
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    const std::string real = vehicleList(30000);
    const std::string bomb = emptyWrappers(8u << 20);
    const auto &type = *pb::GetObjectListResponse::descriptor();
    size_t estimate = 0;
    const double walk = bestSeconds(runs, [&] { estimate = *sortie::hci::estimateDecodedBytes(real, type, SIZE_MAX); });
    const double parse = bestSeconds(runs, [&] {
        pb::GetObjectListResponse parsed;
        if (!parsed.ParseFromString(real))
            std::abort();
    });
    size_t bombEstimate = 0;
    const double refuse = bestSeconds(runs, [&] { bombEstimate = *sortie::hci::estimateDecodedBytes(bomb, type); });
    const double mb = double(real.size()) / 1e6;
    std::printf("real list: %.2f MB, estimated %.1f MB decoded; walk %.2f ms (%.0f MB/s), parse %.2f ms (%.0f MB/s): the walk adds %.0f %%\n",
                mb, double(estimate) / 1e6, walk * 1e3, mb / walk, parse * 1e3, mb / parse, 100.0 * walk / parse);
    std::printf("16 MiB of empty wrappers: refused after %.2f ms (the walk stops past %zu MiB at %.0f MB counted)\n", refuse * 1e3,
                sortie::hci::kHciMaxDecodedBytes >> 20, double(bombEstimate) / 1e6);
    return 0;
}
