// DJI WPML benchmark: the shared 10,000-waypoint route (a wait and a photo series every 50 waypoints)
// written as a KMZ for the Matrice 350 RTK and read back. Prints each figure with its target and the
// KMZ's size; exits 1 if a target is missed. Run: build/tests/mission/bench_wpml
#include "BenchClock.h"
#include "BenchRoute.h"
#include "WpmlFormat.h"

#include <QCoreApplication>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <thread>
#include <vector>

using namespace sortie::mission;
using namespace sortie::mission::formats;

namespace {

using sortie::test::median;
using sortie::test::Timing;

// The target holds on CPU time: on this shared machine the wall time includes waiting for a core.
bool report(const char *what, Timing t, double targetMs)
{
    const bool ok = t.cpuMs < targetMs;
    std::printf("%-36s %10.1f ms wall %10.1f ms cpu   (target < %g ms cpu)%s\n", what, t.wallMs, t.cpuMs, targetMs, ok ? "" : "  MISSED");
    return ok;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    constexpr int kWaypoints = 10000;
    std::printf("Sortie WPML benchmark (%d waypoints, median of 5 runs, %u cores)\n", kWaypoints, std::thread::hardware_concurrency());
    const Route route = benchRoute(kWaypoints);
    WpmlExportOptions options;
    options.drone = QStringLiteral("m350");
    bool ok = true;
    QByteArray kmz;
    int documentBytes = 0;
    ok &= report("export to WPML KMZ", median(5, [&] {
        const Result<WpmlExport> out = writeWpml(route, options);
        if (!out)
            std::printf("refused: %s\n", qPrintable(out.error().message)), std::exit(1);
        kmz = out->kmz;
        documentBytes = int(out->templateKml.size() + out->waylinesWpml.size());
    }), 1000);
    std::printf("%-36s %10.2f MB KMZ (%.2f MB of XML)\n", "  size", kmz.size() / 1e6, documentBytes / 1e6);
    size_t read = 0;
    ok &= report("import the WPML KMZ", median(5, [&] {
        const Result<WpmlImport> in = readWpml(kmz);
        if (!in)
            std::printf("import failed: %s\n", qPrintable(in.error().toString())), std::exit(1);
        read = in->routes.front().segments.size();
    }), 1000);
    if (read != size_t(kWaypoints))
        std::printf("import gave %zu waypoints\n", read), ok = false;
    std::printf(ok ? "all targets met\n" : "TARGETS MISSED\n");
    return ok ? 0 : 1;
}
