#pragma once

#include "FlightModel.h"
#include "HciProto.h"

#include <QString>

#include <vector>

namespace com::ugcs::ucs::proto {
class CommandDefinition;
} // namespace com::ugcs::ucs::proto

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;

// The flight-controller commands a simulated vehicle offers (CommandDefinitions, with `available`
// following its state) and their effect on its FlightModel: arm, disarm, takeoff_command, auto,
// mission_pause, mission_resume, land_command, return_to_home, waypoint (click & go), manual.
class SimCommands
{
public:
    struct Result
    {
        int status = 0; // pb::CommandStatus
        QString error;
    };

    // Definitions for a vehicle; ids are stable per vehicle and command.
    static std::vector<pb::CommandDefinition> definitions(const pb::Vehicle &vehicleRef, const FlightModel &model);
    // One bit per command, set when available: changes mean a CommandEvent is due.
    static quint32 availability(const FlightModel &model);
    static Result execute(FlightModel &model, const pb::Command &command);
};

} // namespace sortie::sim
