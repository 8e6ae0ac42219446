#pragma once

// What every benchmark reads its figures with: the calling thread's CPU time, and the load average to
// print beside them (the machine is shared, so wall time alone says little); the median of repeated
// runs, and whether a figure meets its target.

#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <thread>
#include <vector>

namespace sortie::test {

inline double threadCpuMs()
{
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

inline double loadAverage()
{
    double load = 0;
    if (FILE *f = std::fopen("/proc/loadavg", "r")) {
        if (std::fscanf(f, "%lf", &load) != 1)
            load = 0;
        std::fclose(f);
    }
    return load;
}

// Milliseconds: the median wall and thread-CPU time of repeated runs, and the slowest wall time.
struct Timing
{
    double wallMs = 0;
    double cpuMs = 0;
    double worstMs = 0;
};

// Runs `work` `runs` times (run i is told i) and times each run.
inline Timing measure(int runs, const std::function<void(int run)> &work)
{
    std::vector<double> wall, cpu;
    for (int i = 0; i < runs; ++i) {
        QElapsedTimer timer;
        const double c0 = threadCpuMs();
        timer.start();
        work(i);
        wall.push_back(timer.nsecsElapsed() / 1e6);
        cpu.push_back(threadCpuMs() - c0);
    }
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    return {wall[wall.size() / 2], cpu[cpu.size() / 2], wall.back()};
}

inline Timing median(int runs, const std::function<void()> &work)
{
    return measure(runs, [&work](int) { work(); });
}

// A figure against its target (none when targetMs <= 0). The target is on wall time; on a machine
// busier than its cores (load average above the core count) the wall time includes waiting for a
// core, and the CPU time decides. `note` is what a report prints after the target.
struct Verdict
{
    bool met = true;
    const char *note = "";
};

inline Verdict judge(Timing t, double targetMs)
{
    if (targetMs <= 0 || t.wallMs < targetMs)
        return {};
    const bool busy = loadAverage() > std::thread::hardware_concurrency();
    if (busy && t.cpuMs < targetMs)
        return {true, "  met on CPU time, machine busy"};
    return {false, "  MISSED"};
}

} // namespace sortie::test
