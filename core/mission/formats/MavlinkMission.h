#pragma once

#include "MissionError.h"
#include "Route.h"

#include <QStringList>

#include <memory>

#include <optional>
#include <vector>

namespace sortie::mission {
class ScanPlanCache;
}

namespace sortie::mission::formats {

// MAVLink mission commands and frames the converters know (numbers from the MAVLink common set).
namespace mav {
enum Command {
    NavWaypoint = 16, NavLoiterUnlimited = 17, NavLoiterTurns = 18, NavLoiterTime = 19, NavReturnToLaunch = 20,
    NavLand = 21, NavTakeoff = 22, NavLoiterToAltitude = 31, NavSplineWaypoint = 82, NavVtolTakeoff = 84,
    NavVtolLand = 85, NavDelay = 93, ConditionDelay = 112, ConditionYaw = 115, DoJump = 177, DoChangeSpeed = 178,
    DoSetServo = 183, DoRepeatServo = 184, DoLandStart = 189, DoSetRoiLocation = 195, DoSetRoiNone = 197, DoSetRoi = 201, DoDigicamControl = 203,
    DoMountControl = 205, DoSetCamTriggDist = 206, DoGimbalManagerPitchYaw = 1000, ImageStartCapture = 2000, ImageStopCapture = 2001, VideoStartCapture = 2500,
    VideoStopCapture = 2501, DoVtolTransition = 3000,
};
enum VtolState { VtolStateMulticopter = 3, VtolStateFixedWing = 4 };  // DO_VTOL_TRANSITION's param 1
enum MountMode { MountModeMavlinkTargeting = 2 };
enum Frame { Global = 0, Mission = 2, GlobalRelativeAlt = 3, GlobalInt = 5, GlobalRelativeAltInt = 6,
             GlobalTerrainAlt = 10, GlobalTerrainAltInt = 11 };
}

// One MAVLink mission item as files hold it. Where it came from (line or JSON path) travels with
// it so that a conversion error names the place in the file.
struct MavlinkItem
{
    int command = mav::NavWaypoint;
    int frame = mav::GlobalRelativeAlt;
    double param[4] = {0, 0, 0, 0};
    double latitude = 0, longitude = 0, altitude = 0;  // params 5-7
    bool autoContinue = true;
    int line = 0;          // 1-based source line (WPL), 0 if none
    QString jsonPath;      // source JSON path (.plan), empty if none
    // Set for a survey that a format keeps whole (a .plan complex item): the item stands for the
    // area-scan segment and its command is ignored.
    std::shared_ptr<const AreaScan> scan;
    // Set for another segment a format keeps whole (a .plan corridor scan): the item stands for it.
    std::shared_ptr<const AlgorithmSegment> segment;
};

struct ImportedRoute
{
    Route route;
    QStringList notices;  // what was approximated or skipped, for the operator
};

struct MavlinkExport
{
    std::vector<MavlinkItem> items;
    QStringList notices;
};

// Items -> route. Waypoints before any speed change fly at startSpeed. Commands that have no
// place in the model are skipped with a notice; a navigation command that cannot be placed is an
// error naming its line or path.
Result<ImportedRoute> routeFromMavlink(const std::vector<MavlinkItem> &items, std::optional<HomePosition> home,
                                       double startSpeed);
// Route -> items, assuming the vehicle starts at startSpeed. Area scans are expanded into their
// transects with distance triggering.
// With keepScans, each area scan becomes one item carrying it (for formats with survey items).
MavlinkExport routeToMavlink(const Route &route, double startSpeed, ScanPlanCache *cache = nullptr, bool keepScans = false);

QString mavCommandName(int command);

} // namespace sortie::mission::formats
