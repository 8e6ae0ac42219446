#include "SimNfzService.h"

#include "HciRequestDispatcher.h"
#include "Messages.pb.h"
#include "SimWorld.h"
#include "SimZones.h"

#include <cmath>

namespace sortie::sim {

namespace {

void list(SimCall &call, SimWorld &world)
{
    const auto &r = static_cast<const pb::GetNfzListRequest &>(call.request);
    const SimZones::Box box{r.minlatitude(), r.minlongitude(), r.maxlatitude(), r.maxlongitude()};
    for (double v : {box.minLatitude, box.minLongitude, box.maxLatitude, box.maxLongitude})
        if (!std::isfinite(v)) {
            call.respond.error(QStringLiteral("GetNfzListRequest: the box is not a box (a coordinate is not a number)"));
            return;
        }
    if (box.minLatitude > box.maxLatitude || box.minLongitude > box.maxLongitude) {
        call.respond.error(QStringLiteral("GetNfzListRequest: the box's minimum is above its maximum (radians; the simulator does not "
                                          "support a box across ±180°)"));
        return;
    }
    const std::vector<int> types(r.types().begin(), r.types().end());
    pb::GetNfzListResponse response;
    for (const pb::NoFlightZone *zone : SimZones::list(world.store(), box, types))
        *response.add_zones() = *zone;
    call.respond.reply(response);
}

} // namespace

void SimNfzService::install(HciRequestDispatcher &d, SimWorld &world)
{
    d.add(pb::GetNfzListRequest::default_instance(), HciRequestDispatcher::Access::LoggedIn, [&world](SimCall &c) { list(c, world); });
}

} // namespace sortie::sim
