#pragma once

// What a VehicleLink command answered, for tests that wait on it: QTRY_VERIFY(arm.done).
#include "VehicleLink.h"

namespace sortie::test {

struct CommandCatcher
{
    bool done = false;
    vehicle::CommandResult result;
    vehicle::VehicleLink::Done callback()
    {
        return [this](const vehicle::CommandResult &r) {
            done = true;
            result = r;
        };
    }
};

} // namespace sortie::test
