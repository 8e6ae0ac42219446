#pragma once

// What every benchmark reads its figures with: the calling thread's CPU time, and the load average to
// print beside them (the machine is shared, so wall time alone says little).

#include <cstdio>
#include <ctime>

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

} // namespace sortie::test
