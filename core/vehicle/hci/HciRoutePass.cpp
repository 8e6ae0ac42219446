#include "HciRoutePass.h"

#include "Messages.pb.h"
#include "TelemetryField.h"

#include <algorithm>
#include <QCoreApplication>

namespace sortie::vehicle {

namespace pb = com::ugcs::ucs::proto;
using Kind = HciRoutePassTracker::Outcome::Kind;

namespace {

HciRoutePassTracker::Outcome dropped(const QString &reason)
{
    return {Kind::Dropped, {}, reason};
}

TelemetryBatch missionBatch(int current, int reached, int count, MissionState state, int64_t time)
{
    return {{TelemetryField::MissionCurrent, double(current), time},
            {TelemetryField::MissionReached, double(reached), time},
            {TelemetryField::MissionCount, double(count), time},
            {TelemetryField::MissionState, double(state), time}};
}

} // namespace

HciRoutePassTracker::HciRoutePassTracker(int vehicleId)
    : m_vehicleId(vehicleId)
{
}

HciRoutePassTracker::Outcome HciRoutePassTracker::apply(const pb::ObjectModificationEvent &event, int64_t timeMs)
{
    const int id = event.objectid();
    if (event.objecttype() != "RoutePass")
        return dropped(QCoreApplication::translate("HciRoutePass", "a RoutePass event names the object type \"%1\"").arg(QString::fromStdString(event.objecttype())));
    if (event.modificationtype() == pb::MT_DELETE)
        return removed(id, timeMs);
    if (!event.object().has_routepass())
        return dropped(QCoreApplication::translate("HciRoutePass", "RoutePass %1: the event carries no RoutePass").arg(id));
    return update(event.object().routepass(), id, timeMs);
}

HciRoutePassTracker::Outcome HciRoutePassTracker::apply(const pb::RoutePass &pass, int64_t timeMs)
{
    return update(pass, pass.id(), timeMs);
}

HciRoutePassTracker::Outcome HciRoutePassTracker::update(const pb::RoutePass &pass, int objectId, int64_t timeMs)
{
    if (!pass.has_vehicle() || !pass.vehicle().has_id())
        return dropped(QCoreApplication::translate("HciRoutePass", "RoutePass %1 names no vehicle").arg(objectId));
    if (pass.vehicle().id() != m_vehicleId)
        return {}; // another vehicle's route
    if (!pass.has_waypointcount() || pass.waypointcount() < 1)
        return dropped(QCoreApplication::translate("HciRoutePass", "RoutePass %1 has no waypoint count").arg(objectId));
    const int serverCount = pass.waypointcount();
    if (pass.has_waypointindex() && (pass.waypointindex() < 0 || pass.waypointindex() >= serverCount))
        return dropped(QCoreApplication::translate("HciRoutePass", "RoutePass %1: waypoint index %2 is outside the route's %3 waypoints")
                           .arg(objectId).arg(pass.waypointindex()).arg(serverCount));
    // One more waypoint than we uploaded: the server put the vehicle's own position first (UploadRoute's
    // addFirstWaypoint), which is not a waypoint of the mission the fly view draws.
    const int shift = m_uploadedCount > 0 && serverCount == m_uploadedCount + 1 ? 1 : 0;
    m_passId = objectId;
    m_count = serverCount - shift;
    if (!pass.has_waypointindex()) { // on board, not yet flown
        m_active = -1;
        return {Kind::Applied, missionBatch(-1, 0, m_count, MissionState::Idle, timeMs), {}};
    }
    m_active = std::max(0, pass.waypointindex() - shift);
    return {Kind::Applied, missionBatch(m_active, m_active, m_count, MissionState::Active, timeMs), {}};
}

HciRoutePassTracker::Outcome HciRoutePassTracker::removed(int objectId, int64_t timeMs)
{
    if (objectId != m_passId || m_passId < 0)
        return {}; // not the pass we follow
    // Removed once fully processed, that is after its last waypoint; removed earlier, the route is
    // no longer being executed (replaced by another upload, or cancelled on the server).
    const bool complete = m_count > 0 && m_active == m_count - 1;
    m_passId = -1;
    m_active = -1;
    return {Kind::Applied, missionBatch(-1, complete ? m_count : 0, m_count, complete ? MissionState::Complete : MissionState::Idle, timeMs), {}};
}

} // namespace sortie::vehicle
