#pragma once

#include "AirspaceCheck.h"
#include "AirspaceRule.h"
#include "JsonCursor.h"

#include <QStringList>

#include <memory>
#include <optional>

namespace sortie::plan {

// The zones of --zones FILE (each file: .plan, .geojson / .json, .kml) and the buffer. problems:
// the features each file left out, naming them.
struct ZoneInput
{
    std::shared_ptr<const airspace::ZoneSet> zones;
    double buffer = 20.0;
    QStringList problems;
};

// nullopt with `error` (the file and the reason) when a file cannot be read at all.
std::optional<ZoneInput> readZoneInput(const QStringList &files, double buffer, QString *error);

// {"zones": N, "zonesOutsideWindow": M, "buffer": B, "window": {"from", "to"} | null,
// "violations": [{"zone", "kind", "leg", "fromDistance", "toDistance", "heightUnknown", "message",
// "identifier", "restriction", "volume"}], "warnings": [the same keys (REQ_AUTHORISATION with an
// authorisation, also "authorisation"; CONDITIONAL), or {"zone", "leg", "clearance", "message"} for a
// leg near a zone], "information": [the same keys as violations (NO_RESTRICTION)]}; legs from 1;
// identifier, restriction and volume null for zones that are not geographical zones.
mission::formats::Json airspaceJson(const airspace::AirspaceReport &report, const ZoneInput &input,
                                    const airspace::Authorisations &authorisations = {},
                                    const std::optional<airspace::ed::TimeWindow> &window = std::nullopt);

} // namespace sortie::plan
