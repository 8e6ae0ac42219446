#pragma once

#include "EnergyFit.h"

#include <QStringList>

namespace sortie::endurance::fit {

// The flights of one or more flight logs, ready to fit: every vehicle that reports its battery
// (or only the one named). A file that cannot be read is named with the reason.
struct LoadedFlights
{
    std::vector<FlightTrace> traces;
    QStringList failures; // a log that could not be read at all, and why
    QStringList warnings; // read in part, or a vehicle left out, and why
};

LoadedFlights loadFlights(const QStringList &paths, const QString &vehicle = {});

// The fit as sortie-log prints it: each figure with its spread and sample count, or why it is missing.
QString fitReport(const EnergyFit &fit);

} // namespace sortie::endurance::fit
