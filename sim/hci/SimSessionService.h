#pragma once

#include "SimServices.h"

namespace sortie::sim {

class HciRequestDispatcher;
struct SimCall;

// AuthorizeHci (new session or re-attach), Login, Logout, SetHciLocale. Protocol 2.x only; a licence
// limit on logged-in sessions (SimWorld::Config::maxSessions) is reported as UgCS does (code 1001).
class SimSessionService
{
public:
    explicit SimSessionService(SimServices services);
    void install(HciRequestDispatcher &dispatcher);

private:
    void authorize(SimCall &call);
    void login(SimCall &call);
    void logout(SimCall &call);
    void setLocale(SimCall &call);

    SimServices m_s;
};

} // namespace sortie::sim
