#include "Route.h"

namespace sortie::mission {

PlanContext planContextOf(const RouteSettings &settings)
{
    PlanContext context;
    context.cameras = settings.profile.cameras;
    if (settings.initialSpeed > 0)
        context.defaultSpeed = settings.initialSpeed;
    return context;
}

} // namespace sortie::mission
