#include "HciRouteMapper.h"

#include "CameraProto.h"
#include "Domain.pb.h"
#include "HciOrigin.h"
#include "HciSegmentMapper.h"
#include "HciText.h"
#include <QCoreApplication>

namespace sortie::mission {

namespace pb = com::ugcs::ucs::proto;

namespace {
RouteSettings settingsFromHci(const pb::Route &r)
{
    RouteSettings s;
    s.name = QString::fromStdString(r.name());
    if (r.has_safealtitude()) s.safeAltitude = r.safealtitude();
    if (r.has_maxaltitude()) s.maxAltitude = r.maxaltitude();
    if (r.has_initialspeed()) s.initialSpeed = r.initialspeed();
    if (r.has_maxspeed()) s.maxSpeed = r.maxspeed();
    s.cornerRadius = r.cornerradius();
    s.takeoffHeight = r.takeoffheight();
    s.checkAerodromeNfz = r.checkaerodromenfz();
    s.checkCustomNfz = r.checkcustomnfz();
    for (const auto &f : r.failsafes())
        s.failsafes.push_back({FailsafeReason(int(f.reason())), FailsafeAction(int(f.action()))});
    const pb::VehicleProfile &vp = r.vehicleprofile();
    s.profile.name = QString::fromStdString(vp.name());
    s.profile.cameras = profileCameras(vp);  // read-only here: the server's payloads, never written back
    double maxClimb = 0, maxDescent = 0;
    for (const auto &p : vp.parameters()) {
        switch (p.type()) {
        case pb::VPT_MAX_HORIZONTAL_SPEED: s.profile.maxHorizontalSpeed = p.value(); break;
        case pb::VPT_DEFAULT_CLIMB_RATE: s.profile.climbRate = p.value(); break;
        case pb::VPT_DEFAULT_DESCENT_RATE: s.profile.descentRate = p.value(); break;
        case pb::VPT_MAX_CLIMB_RATE: maxClimb = p.value(); break;
        case pb::VPT_MAX_DESCENT_RATE: maxDescent = p.value(); break;
        case pb::VPT_SAFE_DISTANCE_TO_TERRAIN:
            if (p.value() >= 0)
                s.profile.safeTerrainDistance = p.value();
            break;
        default: break;
        }
    }
    // Without default rates the maximum rates are the best estimate for flight time.
    bool hasDefaultClimb = false, hasDefaultDescent = false;
    for (const auto &p : vp.parameters()) {
        hasDefaultClimb |= p.type() == pb::VPT_DEFAULT_CLIMB_RATE;
        hasDefaultDescent |= p.type() == pb::VPT_DEFAULT_DESCENT_RATE;
    }
    if (!hasDefaultClimb && maxClimb > 0) s.profile.climbRate = maxClimb;
    if (!hasDefaultDescent && maxDescent > 0) s.profile.descentRate = maxDescent;
    return s;
}

// Sets the last parameter of the type: the one settingsFromHci reads when there are several.
void setProfileParameter(pb::VehicleProfile &vp, pb::VehicleParameterType type, double value)
{
    auto *params = vp.mutable_parameters();
    for (int i = params->size() - 1; i >= 0; --i) {
        pb::VehicleParameter &p = *params->Mutable(i);
        if (p.type() == type) {
            if (differs(p.value(), value))
                p.set_value(value);
            return;
        }
    }
    auto *p = vp.add_parameters();
    p->set_type(type);
    p->set_value(value);
}

void settingsToHci(const RouteSettings &s, const RouteSettings *before, pb::Route &r)
{
    if (!before || before->name != s.name) r.set_name(s.name.toStdString());
    if (!before || differs(before->safeAltitude, s.safeAltitude)) r.set_safealtitude(s.safeAltitude);
    if (!before || differs(before->maxAltitude, s.maxAltitude)) r.set_maxaltitude(s.maxAltitude);
    if (!before || differs(before->initialSpeed, s.initialSpeed)) r.set_initialspeed(s.initialSpeed);
    if (!before || differs(before->maxSpeed, s.maxSpeed)) r.set_maxspeed(s.maxSpeed);
    if ((!before && s.cornerRadius != 0) || (before && differs(before->cornerRadius, s.cornerRadius))) r.set_cornerradius(s.cornerRadius);
    if ((!before && s.takeoffHeight != 0) || (before && differs(before->takeoffHeight, s.takeoffHeight))) r.set_takeoffheight(s.takeoffHeight);
    // A new route says both flags; a server's keeps them as it sent them unless they changed.
    if (!before || before->checkAerodromeNfz != s.checkAerodromeNfz) r.set_checkaerodromenfz(s.checkAerodromeNfz);
    if (!before || before->checkCustomNfz != s.checkCustomNfz) r.set_checkcustomnfz(s.checkCustomNfz);
    if (!before || before->failsafes != s.failsafes) {
        auto *list = r.mutable_failsafes();
        while (list->size() > int(s.failsafes.size()))
            list->RemoveLast();
        for (size_t i = 0; i < s.failsafes.size(); ++i) {
            pb::Failsafe *f = int(i) < list->size() ? list->Mutable(int(i)) : r.add_failsafes();
            if (!f->has_reason() || int(f->reason()) != int(s.failsafes[i].reason))
                f->set_reason(pb::FailsafeReason(int(s.failsafes[i].reason)));
            if (!f->has_action() || int(f->action()) != int(s.failsafes[i].action))
                f->set_action(pb::FailsafeAction(int(s.failsafes[i].action)));
        }
    }
    if (before) {
        const VehicleProfile &b = before->profile, &p = s.profile;
        if (b.name != p.name) r.mutable_vehicleprofile()->set_name(p.name.toStdString());
        if (differs(b.maxHorizontalSpeed, p.maxHorizontalSpeed))
            setProfileParameter(*r.mutable_vehicleprofile(), pb::VPT_MAX_HORIZONTAL_SPEED, p.maxHorizontalSpeed);
        if (differs(b.climbRate, p.climbRate)) setProfileParameter(*r.mutable_vehicleprofile(), pb::VPT_DEFAULT_CLIMB_RATE, p.climbRate);
        if (differs(b.descentRate, p.descentRate)) setProfileParameter(*r.mutable_vehicleprofile(), pb::VPT_DEFAULT_DESCENT_RATE, p.descentRate);
        if (differs(b.safeTerrainDistance, p.safeTerrainDistance))
            setProfileParameter(*r.mutable_vehicleprofile(), pb::VPT_SAFE_DISTANCE_TO_TERRAIN, p.safeTerrainDistance);
    }
}
}

Result<HciRouteImport> routeFromHci(const pb::Route &route)
{
    HciRouteImport out;
    out.route.settings = settingsFromHci(route);
    const HciSegmentContext ctx{out.route.settings.initialSpeed, route.has_vehicleprofile() ? &route.vehicleprofile() : nullptr};
    for (int i = 0; i < route.segments_size(); ++i) {
        Result<Segment> s = segmentFromHci(route.segments(i), ctx, &out.notices);
        if (!s) {
            MissionError e = s.error();
            e.message = QCoreApplication::translate("HciRouteMapper", "Route \"%1\", segment %2: %3").arg(out.route.settings.name).arg(i + 1).arg(e.message);
            return e;
        }
        out.route.segments.push_back(std::move(s).value());
    }
    pb::Route origin = route;
    origin.clear_segments();  // segments keep their own origins
    out.route.origin = hciOrigin(std::move(origin));
    return out;
}

pb::Route routeToHci(const Route &route)
{
    pb::Route out;
    std::optional<RouteSettings> before;
    const pb::Route *origin = hciRoute(route.origin);
    if (origin) {
        out = *origin;
        before = settingsFromHci(*origin);
    }
    settingsToHci(route.settings, before ? &*before : nullptr, out);
    // Segments are decoded against the original route's context, so "unchanged" means unchanged.
    const pb::Route &contextRoute = origin ? *origin : out;
    const HciSegmentContext ctx{before ? before->initialSpeed : route.settings.initialSpeed,
                                contextRoute.has_vehicleprofile() ? &contextRoute.vehicleprofile() : nullptr};
    out.clear_segments();
    for (const Segment &s : route.segments)
        *out.add_segments() = segmentToHci(s, ctx);
    return out;
}

Result<Mission> missionFromHci(const pb::Mission &mission, QStringList *notices)
{
    Mission out;
    out.name = QString::fromStdString(mission.name());
    out.description = QString::fromStdString(mission.description());
    for (const pb::Route &r : mission.routes()) {
        Result<HciRouteImport> route = routeFromHci(r);
        if (!route)
            return route.error();
        if (notices)
            *notices << route->notices;
        out.routes.push_back(std::move(route).value().route);
    }
    pb::Mission origin = mission;
    origin.clear_routes();
    out.origin = hciOrigin(std::move(origin));
    return out;
}

pb::Mission missionToHci(const Mission &mission)
{
    pb::Mission out;
    const pb::Mission *origin = hciMission(mission.origin);
    if (origin)
        out = *origin;
    if (!origin || QString::fromStdString(out.name()) != mission.name)
        out.set_name(mission.name.toStdString());
    if (!origin || QString::fromStdString(out.description()) != mission.description)
        out.set_description(mission.description.toStdString());
    out.clear_routes();
    for (const Route &r : mission.routes)
        *out.add_routes() = routeToHci(r);
    return out;
}

} // namespace sortie::mission
