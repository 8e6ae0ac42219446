#pragma once

#include <QString>

#include <vector>

namespace sortie::mission::formats {

// A camera or sensor on a DJI gimbal, as WPML names it (payloadEnumValue: DJI Cloud API "Enumeration
// Values of Camera", the type of type-subtype-gimbalindex), with the gimbal's pitch range.
struct DjiPayload
{
    QString key;    // "h20t", "m3e-camera"
    QString name;   // "Zenmuse H20T"
    int enumValue = 0;
    int subEnumValue = 0;
    double gimbalPitchMinDeg = -90.0;
    double gimbalPitchMaxDeg = 30.0;
};

// A DJI aircraft DJI Pilot 2 flies WPML routes with (droneEnumValue/droneSubEnumValue: DJI Cloud API
// "Enumeration Values of Aircraft"), and the limits Sortie checks before writing a route for it.
struct DjiDroneModel
{
    QString key;   // "m350"
    QString name;  // "DJI Matrice 350 RTK", as UgCS names its vehicle profile
    int droneEnumValue = 0;
    int droneSubEnumValue = 0;
    std::vector<DjiPayload> payloads;  // the first is the default
    double maxWaypointSpeed = 15.0;    // m/s: waypoint missions fly at most 15 m/s on every model
    double maxHorizontalSpeed = 15.0;  // m/s: the airframe, in manual flight
    double maxClimbRate = 5.0;         // m/s
    double maxDescentRate = 4.0;       // m/s
    double maxAltitudeLimit = 1500.0;  // m above take-off: the highest altitude limit the app can set
    bool followsSurface = false;       // realTimeFollowSurface (terrain following in flight) is offered
    bool startActions = false;         // wpml:startActionGroup (actions before the wayline) is flown
};

const std::vector<DjiDroneModel> &djiDroneModels();
// By key ("m300", "m350", "m30", "m3e", ...) or by name, case-insensitively; null when unknown.
const DjiDroneModel *findDjiDroneModel(const QString &keyOrName);
// By the droneInfo a WPML file declares; null when Sortie does not know the aircraft.
const DjiDroneModel *findDjiDroneModel(int droneEnumValue, int droneSubEnumValue);
const DjiPayload *findDjiPayload(const DjiDroneModel &model, const QString &key);
// "m300, m350, m30, ...": for error messages and --help.
QString djiDroneKeys();

} // namespace sortie::mission::formats
