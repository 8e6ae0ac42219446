#include "AirspaceReport.h"

#include "AirspaceRule.h"
#include "ZoneFiles.h"

#include <cmath>

namespace sortie::plan {

using mission::formats::Json;

namespace {
Json metres(double v)
{
    return std::isfinite(v) ? Json(std::round(v * 1000.0) / 1000.0) : Json(nullptr);
}
} // namespace

std::optional<ZoneInput> readZoneInput(const QStringList &files, double buffer, QString *error)
{
    ZoneInput input;
    input.buffer = buffer;
    std::vector<airspace::Zone> zones;
    for (const QString &file : files) {
        const mission::Result<airspace::ZoneFile> read = airspace::loadZoneFile(file);
        if (!read) {
            *error = read.error().toString();
            return std::nullopt;
        }
        for (const QString &p : read->problems)
            input.problems << QStringLiteral("%1: %2").arg(file, p);
        zones.insert(zones.end(), read->zones.begin(), read->zones.end());
    }
    input.zones = std::make_shared<const airspace::ZoneSet>(std::move(zones));
    return input;
}

Json airspaceJson(const airspace::AirspaceReport &report, const ZoneInput &input)
{
    const auto &zones = input.zones->zones();
    Json violations = Json::array(), warnings = Json::array();
    for (const airspace::AirspaceViolation &v : report.violations)
        violations.push_back({{"zone", zones[size_t(v.zone)].name.toStdString()},
                              {"kind", airspace::violationKindName(v.kind).toStdString()},
                              {"leg", v.leg},
                              {"fromDistance", metres(v.fromDistance)},
                              {"toDistance", metres(v.toDistance)},
                              {"heightUnknown", v.heightUnknown},
                              {"message", airspace::violationMessage(v, zones[size_t(v.zone)]).toStdString()}});
    for (const airspace::AirspaceWarning &w : report.warnings)
        warnings.push_back({{"zone", zones[size_t(w.zone)].name.toStdString()},
                            {"leg", w.leg},
                            {"clearance", metres(w.clearance)},
                            {"message", airspace::warningMessage(w, zones[size_t(w.zone)], input.buffer).toStdString()}});
    return Json{{"zones", report.zones}, {"buffer", input.buffer}, {"violations", std::move(violations)}, {"warnings", std::move(warnings)}};
}

} // namespace sortie::plan
