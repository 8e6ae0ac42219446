#pragma once

#include "MissionError.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace sortie::endurance {

// Where a vehicle's energy numbers came from; the UI and the CLI say which.
enum class ProfileSource { File, Server, Fit };

// What a vehicle's battery holds and what each way of flying costs. Powers are electrical (what
// leaves the battery), in watts; speeds and rates in m/s. A value an input did not give stays
// empty rather than 0: an estimate from a profile without power figures is refused, not guessed.
struct EnergyProfile
{
    QString name;
    ProfileSource source = ProfileSource::File;
    double batteryWh = 0.0;          // usable energy of one full battery
    double reserve = 0.2;            // fraction of batteryWh to be left at landing
    double cruiseSpeed = 0.0;        // m/s: the speed cruisePowerW was measured at
    double climbRate = 0.0;          // m/s
    double descentRate = 0.0;        // m/s
    double hoverPowerW = 0.0;
    double cruisePowerW = 0.0;
    double climbPowerW = 0.0;        // at climbRate, straight up
    double descentPowerW = 0.0;      // at descentRate, straight down
    std::optional<double> acceleration; // m/s², where known: speeding up and slowing down take time

    // Power in level flight at an air speed. Between hover (0) and cruiseSpeed it follows
    // P(v) = hover + (cruise - hover)·(v/cruiseSpeed)²; above cruiseSpeed it grows with the cube
    // of the speed, as parasitic drag power does: P(v) = cruise·(v/cruiseSpeed)³.
    double levelPowerW(double airSpeed) const;
    double usableWh() const { return batteryWh * (1.0 - reserve); }

    // Empty when every figure an estimate needs is there and sane; otherwise what is wrong.
    QString problem() const;

    bool operator==(const EnergyProfile &) const = default;
};

QString sourceName(ProfileSource source);

// The JSON file form (docs/endurance.md): an object with the fields above by their names; the
// optional "source" is "file" (the default), "server" or "fit". A missing required number, a
// negative one or a reserve outside [0, 1) is an error naming the JSON path.
mission::Result<EnergyProfile> readEnergyProfile(const QByteArray &json);
// The file at `path` read (at most 1 MiB: a profile is a few hundred bytes) and parsed; an error
// names the file. The client and sortie-plan both load profiles through here.
mission::Result<EnergyProfile> loadEnergyProfile(const QString &path);
QByteArray writeEnergyProfile(const EnergyProfile &profile);

} // namespace sortie::endurance
