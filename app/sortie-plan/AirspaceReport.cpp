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

Json airspaceJson(const airspace::AirspaceReport &report, const ZoneInput &input, const airspace::Authorisations &authorisations,
                  const std::optional<airspace::ed::TimeWindow> &window)
{
    const auto &zones = input.zones->zones();
    Json violations = Json::array(), warnings = Json::array(), information = Json::array();
    for (const airspace::AirspaceViolation &v : report.violations) {
        const airspace::Zone &zone = zones[size_t(v.zone)];
        Json entry{{"zone", zone.name.toStdString()},
                   {"kind", airspace::violationKindName(v.kind).toStdString()},
                   {"leg", v.leg},
                   {"fromDistance", metres(v.fromDistance)},
                   {"toDistance", metres(v.toDistance)},
                   {"heightUnknown", v.heightUnknown},
                   {"message", airspace::violationMessage(v, zone, authorisations).toStdString()},
                   {"identifier", zone.geoZone ? Json(zone.geoZone->identifier.toStdString()) : Json(nullptr)},
                   {"restriction", zone.geoZone ? Json(airspace::ed::restrictionName(zone.geoZone->restriction).toStdString()) : Json(nullptr)},
                   {"volume", zone.geoZone ? Json(zone.volume) : Json(nullptr)}};
        switch (airspace::findingLevel(v, zone, authorisations)) {
        case airspace::FindingLevel::Error: violations.push_back(std::move(entry)); break;
        case airspace::FindingLevel::Warning:
            if (const QString reference = airspace::authorisationFor(zone, authorisations); !reference.isEmpty())
                entry["authorisation"] = reference.toStdString();
            warnings.push_back(std::move(entry));
            break;
        case airspace::FindingLevel::Information: information.push_back(std::move(entry)); break;
        }
    }
    for (const airspace::AirspaceWarning &w : report.warnings)
        warnings.push_back({{"zone", zones[size_t(w.zone)].name.toStdString()},
                            {"leg", w.leg},
                            {"clearance", metres(w.clearance)},
                            {"message", airspace::warningMessage(w, zones[size_t(w.zone)], input.buffer).toStdString()}});
    Json when = nullptr;
    if (window)
        when = Json{{"from", window->from.toUTC().toString(Qt::ISODate).toStdString()}, {"to", window->to.toUTC().toString(Qt::ISODate).toStdString()}};
    return Json{{"zones", report.zones},
                {"zonesOutsideWindow", report.outsideWindow},
                {"buffer", input.buffer},
                {"window", std::move(when)},
                {"violations", std::move(violations)},
                {"warnings", std::move(warnings)},
                {"information", std::move(information)}};
}

} // namespace sortie::plan
