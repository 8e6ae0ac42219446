#pragma once

#include "AirspaceCheck.h"
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

// {"zones": N, "buffer": B, "violations": [{"zone", "kind", "leg", "fromDistance", "toDistance",
// "heightUnknown", "message"}], "warnings": [{"zone", "leg", "clearance", "message"}]}; legs from 1.
mission::formats::Json airspaceJson(const airspace::AirspaceReport &report, const ZoneInput &input);

} // namespace sortie::plan
