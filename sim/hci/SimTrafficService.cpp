#include "SimTrafficService.h"

#include "HciRequestDispatcher.h"
#include "Messages.pb.h"
#include "SimTraffic.h"

#include <QDateTime>

#include <cmath>
#include <numbers>

namespace sortie::sim {
namespace pb = com::ugcs::ucs::proto;
namespace {
constexpr double kDeg = 180.0 / std::numbers::pi;
} // namespace

void SimTrafficService::install(HciRequestDispatcher &d, const SimTraffic &traffic)
{
    d.add(pb::GetAdsbAircraftListRequest::default_instance(), HciRequestDispatcher::Access::LoggedIn, [&traffic](SimCall &c) {
        const auto &r = static_cast<const pb::GetAdsbAircraftListRequest &>(c.request);
        const double lat = r.location().latitude() * kDeg, lon = r.location().longitude() * kDeg;
        if (!std::isfinite(lat) || !std::isfinite(lon) || std::abs(lat) > 90 || std::abs(lon) > 180)
            return c.respond.error(QStringLiteral("The location is not on the globe (latitude and longitude are in radians)"));
        if (!std::isfinite(r.radius()) || r.radius() <= 0)
            return c.respond.error(QStringLiteral("radius must be a positive number of metres, not %1").arg(r.radius()));
        pb::GetAdsbAircraftListResponse out;
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        for (const SimAircraft &a : traffic.aircraftWithin(lat, lon, r.radius())) {
            pb::AdsbAircraft *x = out.add_aircrafts();
            x->set_icaoaddress(int32_t(a.address));
            x->set_icaoaddresstype(pb::IAT_REAL);
            x->set_updatetime(now);
            x->set_identification(a.callsign.toStdString());
            x->set_latitude(a.latitude / kDeg);
            x->set_longitude(a.longitude / kDeg);
            x->set_mslaltitude(a.altitudeM);
            x->set_heading(a.trackDeg / kDeg);
            x->set_groundspeed(a.groundSpeedMps);
            x->set_verticalvelocity(a.verticalRateMps);
        }
        c.respond.reply(out);
    });
}

} // namespace sortie::sim
