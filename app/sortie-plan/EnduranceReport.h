#pragma once

#include "EnduranceEstimate.h"
#include "JsonCursor.h"

#include <QString>
#include <QTextStream>

#include <optional>

namespace sortie::plan {

// The endurance options of `sortie-plan stats`: --vehicle PROFILE.json, --wind SPEED,FROM_DEG,
// --turns coordinated|stop. nullopt with `error` set (naming the file and line or JSON path) when
// one cannot be read.
struct EnduranceInput
{
    endurance::EnergyProfile profile;
    endurance::FlightConditions conditions;
};
std::optional<EnduranceInput> readEnduranceInput(const QString &vehicleFile, const QString &wind, const QString &turns, QString *error);

// The "endurance" object of stats' JSON: flightTime (s), energyWh, batteryAtEnd (fraction of one
// battery), batteriesNeeded, pointOfNoReturn {leg, distance} or null, legs [{leg, time, energyWh}],
// and more (the profile, the reserve, the battery changes). Legs count from 1 as `profile` counts
// them; the flight home is the leg after the last; distances are metres along the route.
mission::formats::Json enduranceJson(const EnduranceInput &input, const endurance::EnduranceEstimate &estimate);
void printEndurance(QTextStream &out, const mission::Route &route, const EnduranceInput &input,
                    const endurance::EnduranceEstimate &estimate);

} // namespace sortie::plan
