// How fast the SBS-1 reader reads: lines per second through SbsReader, for a feed of the three
// kinds a receiver sends most (identification, airborne position, velocity), pushed in 4 KiB chunks
// as a socket delivers them. Prints the figure for docs/performance.md.
#include "SbsReader.h"

#include <QElapsedTimer>

#include <cstdio>
#include <ctime>
#include <string>

using namespace sortie::traffic::sbs;

int main()
{
    const std::string time = "2026/11/26,18:44:00.123,2026/11/26,18:44:00.125";
    std::string feed;
    for (int i = 0; i < 1000; ++i) {
        char address[8];
        std::snprintf(address, sizeof address, "%06X", 0x400000 + i % 300);
        feed += "MSG,1,1,1," + std::string(address) + ",1," + time + ",RYR" + std::to_string(i % 1000) + ",,,,,,,,,,,\r\n";
        feed += "MSG,3,1,1," + std::string(address) + ",1," + time + ",,37000,,,56.97650,24.07600,,,0,0,0,0\r\n";
        feed += "MSG,4,1,1," + std::string(address) + ",1," + time + ",,,452,271,,,-64,,0,0,0,0\r\n";
    }
    constexpr int kRounds = 200;
    constexpr size_t kChunk = 4096;
    uint64_t lines = 0, messages = 0;
    QElapsedTimer timer;
    timer.start();
    const std::clock_t cpuStart = std::clock();
    for (int round = 0; round < kRounds; ++round) {
        SbsReader reader;
        for (size_t at = 0; at < feed.size(); at += kChunk) {
            reader.push(std::string_view(feed).substr(at, kChunk));
            while (auto r = reader.next())
                messages += std::holds_alternative<SbsMessage>(*r) ? 1 : 0;
        }
        lines += reader.linesSeen();
    }
    const double seconds = double(timer.nsecsElapsed()) / 1e9;
    const double cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC; // the machine may be shared: CPU time is the figure
    std::printf("bench_sbs: %llu lines (%llu messages, %.1f MB) in %.3f s CPU (%.3f s wall): %.2f million lines/s, %.0f MB/s of CPU time\n",
                (unsigned long long)lines, (unsigned long long)messages, double(feed.size()) * kRounds / 1e6, cpu, seconds,
                double(lines) / cpu / 1e6, double(feed.size()) * kRounds / 1e6 / cpu);
    return messages == lines ? 0 : 1;
}
