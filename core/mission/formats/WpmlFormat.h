#pragma once

#include "MissionError.h"
#include "Route.h"

#include <QByteArray>
#include <QStringList>

#include <functional>
#include <optional>

namespace sortie::mission {
class ScanPlanCache;
}
namespace sortie::datum {
class Egm96Geoid;
}

namespace sortie::mission::formats {

// DJI WPML (WayPoint Markup Language, DJI Cloud API): a KMZ (ZIP) holding wpmz/template.kml (the
// route as an editable template) and wpmz/waylines.wpml (what the aircraft executes), which DJI
// Pilot 2 imports for the Matrice 300/350 RTK and the Mavic 3 Enterprise series.

// The height reference of the written route.
enum class WpmlHeightMode {
    RelativeToTakeoff,  // relativeToStartPoint: metres above where the aircraft takes off
    Egm96,              // AMSL (EGM96) in the template; the executable file flies them relative to
                        // take-off, so the take-off's AMSL altitude is needed
    AboveGroundLevel,   // realTimeFollowSurface: the aircraft follows the terrain (Mavic 3E series)
    Wgs84,              // the executable file flies WGS-84 ellipsoidal heights (executeHeightMode
                        // WGS84), converted from AMSL with the EGM96 geoid; the template holds EGM96
};
QString wpmlHeightModeName(WpmlHeightMode mode);  // "relative", "amsl", "agl", "wgs84"
bool parseWpmlHeightMode(const QString &name, WpmlHeightMode *out);

// Limits DJI documents for waypoint missions (Mobile SDK waypoint V2, which WPML missions share):
// 2 to 65535 waypoints, adjacent waypoints at least 0.5 m apart, speeds up to 15 m/s (the model's
// own limit is checked too), take-off security height 1.2 to 1500 m.
inline constexpr int kWpmlMinWaypoints = 2;
inline constexpr int kWpmlMaxWaypoints = 65535;
inline constexpr double kWpmlMinLegMeters = 0.5;
inline constexpr double kWpmlMinTakeoffSecurityHeight = 1.2;
inline constexpr double kWpmlMaxTakeoffSecurityHeight = 1500.0;

// Where ellipsoidal heights are converted: a geoid the caller holds, else the EGM96 grid at gridPath
// (empty: Egm96Geoid::defaultGridPath()), opened when a height first needs it. A missing grid is an
// error where a height needs it, never a height passed through unconverted.
struct WpmlGeoid
{
    const datum::Egm96Geoid *geoid = nullptr;
    QString gridPath;
};

struct WpmlExportOptions
{
    // A DjiDroneModel key or name; empty: the route's vehicle profile when it names a DJI aircraft,
    // else the Matrice 350 RTK (with a notice).
    QString drone;
    QString payload;                         // a DjiPayload key; empty: the drone's default camera
    WpmlHeightMode heightMode = WpmlHeightMode::RelativeToTakeoff;
    // AMSL altitude of the take-off point; unset: the route's home (which an imported file's
    // wpml:takeOffRefPoint sets). Needed to write AMSL altitudes relative to take-off. Written back as
    // the template's takeOffRefPoint (ellipsoidal, at the home or the climb point) when known.
    std::optional<double> takeoffAltitudeAmsl;
    WpmlGeoid geoid;
    // Terrain elevation AMSL where known (nullopt where not): converts AGL and AMSL into each other.
    // Without it, such a conversion is refused, except AGL written relative to take-off, which is
    // exact over level ground and reported as a notice (as the MAVLink export does).
    std::function<std::optional<double>(const GeoPoint &)> groundElevationAmsl;
    double takeoffSecurityHeight = 20.0;  // metres: the aircraft climbs this high before the route
    // When set, the wayline starts with a climb over this point (the take-off spot) to the take-off
    // security height, as a UgCS server's "add first waypoint" does: the route then leaves from
    // where the aircraft stands rather than flying straight to its first waypoint.
    std::optional<GeoPoint> climbOver;
    qint64 timestampMs = 0;               // the template's create/update time (0 keeps the output fixed)
};

struct WpmlExport
{
    QByteArray kmz;
    QByteArray templateKml;   // the two documents inside, for tools and tests
    QByteArray waylinesWpml;
    int waypointCount = 0;
    QStringList notices;      // what was approximated, for the operator
};

// Writes the route as it flies: waypoints as they are, area scans as their planned passes with the
// gimbal pointed down and a photo every forward-overlap distance. Refuses, with the row and the
// reason, what the model cannot fly or WPML cannot say: a documented limit passed (waypoint count,
// distance, speed, height), an action with no WPML equivalent, an area scan that cannot be planned.
// The first waypoint's leading gimbal settings become the wayline's startActionGroup on aircraft
// that fly one (DjiDroneModel::startActions).
Result<WpmlExport> writeWpml(const Route &route, const WpmlExportOptions &options = {}, ScanPlanCache *cache = nullptr);
// Several routes as the waylines (Folders) of one file, flown in order: one aircraft, one finish
// action (the last route's; an earlier route that returns home or lands is refused).
Result<WpmlExport> writeWpml(const std::vector<const Route *> &routes, const WpmlExportOptions &options = {},
                             ScanPlanCache *cache = nullptr);

struct WpmlImport
{
    std::vector<Route> routes;  // one per wayline (Folder) of waylines.wpml
    QString droneName;          // the DjiDroneModel the file declares, if known
    QStringList notices;        // "wayline 2, waypoint 7: ...": what is not kept, or kept otherwise
};

struct WpmlReadOptions
{
    WpmlGeoid geoid;
};

// Reads a WPML KMZ (or a bare waylines.wpml): each wayline becomes a route of waypoints with their
// speeds, turn modes and actions. Heights: AMSL from the template when it holds EGM96 heights;
// WGS-84 ellipsoidal heights converted to AMSL with the EGM96 geoid; relative to take-off, AMSL when
// the file holds its take-off point (wpml:takeOffRefPoint, kept as the route's home), else AGL
// (with a notice: equal over level ground). A damaged archive or document fails with the file and
// line; every element not kept is named in a notice.
Result<WpmlImport> readWpml(const QByteArray &data, const WpmlReadOptions &options = {});

} // namespace sortie::mission::formats
