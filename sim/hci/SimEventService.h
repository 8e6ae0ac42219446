#pragma once

#include "SimServices.h"

namespace sortie::sim {

class HciRequestDispatcher;
struct SimCall;

// SubscribeEvent and UnsubscribeEvent. Supports telemetry, object modification, lock, command and
// environment (no-fly zone changes) subscriptions; any other kind is refused with an Error that names it.
class SimEventService
{
public:
    explicit SimEventService(SimServices services);
    void install(HciRequestDispatcher &dispatcher);

private:
    void subscribe(SimCall &call);
    void unsubscribe(SimCall &call);

    SimServices m_s;
};

} // namespace sortie::sim
