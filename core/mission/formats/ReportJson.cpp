#include "ReportJson.h"

namespace sortie::mission::formats {

Json statisticsJson(const RouteStatistics &s)
{
    Json j{{"waypoints", s.waypointCount}, {"areaScans", s.areaScanCount}, {"pathPoints", s.pathPointCount},
           {"lengthMeters", s.lengthMeters}, {"flightTimeSeconds", s.flightTimeSeconds}, {"climbMeters", s.climbMeters},
           {"descentMeters", s.descentMeters}, {"photoCount", s.photoCount}};
    if (!s.boundingBox.empty)
        j["boundingBox"] = {{"south", s.boundingBox.south}, {"west", s.boundingBox.west}, {"north", s.boundingBox.north},
                            {"east", s.boundingBox.east}};
    return j;
}

Json validationJson(const ValidationReport &r)
{
    Json issues = Json::array();
    for (const ValidationIssue &i : r.issues)
        issues.push_back({{"severity", i.severity == Severity::Error ? "error" : "warning"}, {"rule", i.rule.toStdString()},
                          {"segment", i.segment}, {"message", i.message.toStdString()}});
    return Json{{"errors", r.errorCount()}, {"warnings", r.warningCount()}, {"issues", std::move(issues)}};
}

Json scanPlanJson(const AreaScanPlan &p)
{
    return Json{{"transects", p.transects.size()}, {"cells", p.cells}, {"photoCount", p.photoCount},
                {"altitudeMeters", p.altitude}, {"groundSampleDistanceCm", p.groundSampleDistanceCm},
                {"transectSpacingMeters", p.transectSpacing}, {"triggerDistanceMeters", p.triggerDistance},
                {"pathLengthMeters", p.pathLength}, {"areaSquareMeters", p.areaSquareMeters}};
}

} // namespace sortie::mission::formats
