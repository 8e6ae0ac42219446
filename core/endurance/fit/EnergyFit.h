#pragma once

#include "EnergyProfile.h"
#include "FlightTrace.h"
#include "PhaseSegmenter.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace sortie::endurance::fit {

// One fitted figure: its value with the standard deviation of what it was fitted from and how many
// of those there were; or, when the logs had too little of it, why it is missing (never 0).
struct Estimate
{
    std::optional<double> value;
    double spread = kMissing; // standard deviation; NaN with a single sample
    int count = 0;            // samples (flights for the capacity)
    QString missing;          // why there is no value
    bool ok() const { return value.has_value(); }
};

struct FitOptions
{
    PhaseThresholds phases;
    int minSamples = 10;            // per phase, after trimming
    double minFractionUsed = 0.05;  // of the battery, for a flight's capacity estimate
    // The capacity used to turn the remaining fraction into power in logs without current, when no
    // log with current gave one; empty: such logs give no powers.
    std::optional<double> capacityWh;
};

// What the logs say about the vehicle's energy. Powers and rates are means over every sample of
// their phase in every log; cruise is level flight at the most flown level speed (±5 %), climb and
// descent are straight up and down at the most flown rate (±5 %). The capacity is the energy used
// over the fraction of the battery used, over every log that reports current.
struct EnergyFit
{
    Estimate hoverPowerW;
    Estimate cruisePowerW, cruiseSpeed;
    Estimate climbPowerW, climbRate;
    Estimate descentPowerW, descentRate;
    Estimate batteryWh;
    QString capacitySource;   // how batteryWh is known: fitted, given, or nothing
    QStringList notes;        // a trace that gave no powers, and why
    int flights = 0;          // traces used

    // The profile (source Fit, reserve 0.2) when every figure is there; else nullopt and *why.
    std::optional<EnergyProfile> profile(const QString &name, QString *why = nullptr) const;
};

EnergyFit fitEnergy(std::vector<FlightTrace> traces, const FitOptions &options = {});

// Energy used over fraction used for one trace with current (Wh); empty when too little was used.
std::optional<double> capacityOf(const FlightTrace &trace, double minFractionUsed, double *fractionUsed = nullptr);

} // namespace sortie::endurance::fit
