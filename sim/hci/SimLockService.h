#pragma once

#include "SimServices.h"

namespace sortie::sim {

class HciRequestDispatcher;
struct SimCall;

// AcquireLock, ReleaseLock (ifExclusive: release only our own lock, quietly), CheckLock,
// CheckMultipleLocks. Locks are owned by sessions; another session's held lock is refused.
class SimLockService
{
public:
    explicit SimLockService(SimServices services);
    void install(HciRequestDispatcher &dispatcher);

private:
    void acquire(SimCall &call);
    void release(SimCall &call);
    void check(SimCall &call);
    void checkMultiple(SimCall &call);

    SimServices m_s;
};

} // namespace sortie::sim
