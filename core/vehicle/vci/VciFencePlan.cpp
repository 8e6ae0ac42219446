#include "VciFencePlan.h"

namespace sortie::vehicle {

vci::profile::BreachAction profileBreachAction(FenceBreachAction action)
{
    namespace profile = vci::profile;
    switch (action) {
    case FenceBreachAction::Return: return profile::BreachAction::Return;
    case FenceBreachAction::Land: return profile::BreachAction::Land;
    case FenceBreachAction::Hold: return profile::BreachAction::Hold;
    }
    return profile::BreachAction::Return;
}

} // namespace sortie::vehicle
