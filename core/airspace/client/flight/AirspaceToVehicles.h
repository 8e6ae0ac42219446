#pragma once

#include <QMetaObject>

namespace sortie::client {
class MissionUploader;
}

namespace sortie::airspace {

class Airspace;
class ZoneAlertMonitor;

// One airspace for the route check, the in-flight alerts and the fence: what the operator sees is
// what a vehicle is warned of and carries. The zone alerts watch every zone of the airspace; the
// fence an upload sends holds all of them but the open route's own fence (which goes up with the
// route itself). Shared at once and again on every change of the airspace. The client graph makes one.
class AirspaceToVehicles
{
public:
    // `alerts` may be null (a client without vehicles). All must outlive this object.
    AirspaceToVehicles(Airspace *airspace, client::MissionUploader *uploader, ZoneAlertMonitor *alerts);
    ~AirspaceToVehicles();
    AirspaceToVehicles(const AirspaceToVehicles &) = delete;
    AirspaceToVehicles &operator=(const AirspaceToVehicles &) = delete;

    // Whether the airspace's changes reach the uploads' fence (for the graph's wiring lines).
    bool isFollowing() const { return bool(m_changes); }

private:
    void share();

    Airspace *m_airspace;
    client::MissionUploader *m_uploader;
    ZoneAlertMonitor *m_alerts;
    QMetaObject::Connection m_changes;
};

} // namespace sortie::airspace
