#pragma once

#include <QtGlobal>

namespace sortie::test {

// What the kernel says about a process (Linux /proc and getrusage): memory, descriptors, CPU time.
struct ProcessStats
{
    qint64 residentKiB = 0;     // VmRSS
    qint64 peakResidentKiB = 0; // VmHWM
    int openFiles = 0;          // entries in /proc/<pid>/fd
    double cpuSeconds = 0;      // user + system

    // This process (pid 0) or another one.
    static ProcessStats of(qint64 pid = 0);
};

} // namespace sortie::test
