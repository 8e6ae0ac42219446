#pragma once

#include "SimPower.h"
#include "VciWriter.h"

#include <QString>

namespace sortie::sim {

class SimTerrain;

// One simulated VCI vehicle's settings, with the test knobs that make it misbehave on purpose.
struct SimVciOptions
{
    QString id = QStringLiteral("vci-1");
    QString name = QStringLiteral("Sim VCI 1");
    double homeLatitude = 56.9496;   // degrees
    double homeLongitude = 24.1052;  // degrees
    double groundElevation = 12;     // metres AMSL (where `terrain` has no data, or without one)
    // The world's ground (sortie-sim's, shared with the HCI vehicles): the home stands on it and the
    // position's altitudeAgl is above the ground under the vehicle. Not owned; nullptr: flat ground.
    const SimTerrain *terrain = nullptr;
    double telemetryRate = 10;       // NOTIFYs per second per subscribed telemetry resource
    double timeScale = 1;            // simulated seconds per real second (tests fly missions faster)
    // Telemetry times from the vehicle's own clock, which runs at timeScale (from the wall clock at
    // its start), rather than the wall clock: a log of a sped-up flight then has the flight's own
    // durations, so energy integrated over it is right (sortie-log fit).
    bool simulatedClock = false;
    // What flying costs and what its battery holds; its speeds and rates are the vehicle's limits.
    endurance::EnergyProfile energy = simEnergyProfile();
    vci::VciFraming framing = vci::VciFraming::JsonOnly; // how its bodies are delimited

    // Test knobs.
    int answerDelayMs = 0;   // slow answers: each answer waits this long
    int malformedEvery = 0;  // every Nth NOTIFY goes out broken (0: never)
    int dropAfter = 0;       // close the connection after sending this many messages (0: never)
};

} // namespace sortie::sim
