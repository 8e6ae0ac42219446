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
// resident-memory bounds only when this is true, and their heap bounds (heapBytesInUse) always.
#ifdef SORTIE_TEST_ASAN
inline constexpr bool kResidentMemoryIsMeaningful = false;
#else
inline constexpr bool kResidentMemoryIsMeaningful = true;
#endif

// The bytes this process's heap holds for it now: what the program has allocated and not freed.
// Under AddressSanitizer its allocator's own count (freed blocks in the quarantine are not counted),
// else glibc's (mallinfo2: in-use arena bytes plus mmapped blocks). Unlike resident memory this is
// meaningful in both builds, so memory bounds hold under the sanitizers too.
qint64 heapBytesInUse();

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
