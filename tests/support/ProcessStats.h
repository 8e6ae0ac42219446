#pragma once

#include <QtGlobal>

#if defined(__SANITIZE_ADDRESS__)
#define SORTIE_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SORTIE_TEST_ASAN 1
#endif
#endif

namespace sortie::test {

// Under AddressSanitizer freed memory waits in a quarantine before it is reused, so resident memory
// grows whatever the code does; LeakSanitizer checks for leaks at exit instead. Tests assert their
// memory bounds only when this is true.
#ifdef SORTIE_TEST_ASAN
inline constexpr bool kResidentMemoryIsMeaningful = false;
#else
inline constexpr bool kResidentMemoryIsMeaningful = true;
#endif

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
