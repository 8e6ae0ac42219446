#pragma once

#include "EnergyProfile.h"
#include "RouteTiming.h"

#include <optional>
#include <vector>

namespace sortie::mission {
class ScanPlanCache;
}

namespace sortie::endurance {

// How the route is flown beyond what it says itself.
struct FlightConditions
{
    mission::Wind wind;
    mission::TurnMode turns = mission::TurnMode::Coordinated;
};

// The time model's parameters for a vehicle: its energy profile's cruise speed, rates and
// acceleration (the rates its powers were measured at), with the conditions given.
mission::TimingParameters timingFor(const EnergyProfile &profile, const FlightConditions &conditions);

// A place along the route: on leg `leg` (numbered as the timeline), `distance` metres of horizontal
// flight from the route's start.
struct RoutePlace
{
    int leg = 1;
    double distance = 0.0;
    mission::GeoPoint position;
    double altitude = 0.0;
    mission::AltitudeType altitudeType = mission::AltitudeType::Agl;
    int segment = -1;  // the route row of the point (for a leg's end), -1 for home or mid-leg
};

struct LegEnergy
{
    int leg = 1;
    bool returnHome = false;
    double seconds = 0.0;
    double energyWh = 0.0;
    double startWh = 0.0;  // energy used before the leg, from the start of the route
};

// Where a battery is changed: the last leg end reached with the reserve intact on the battery in
// use. Planned when the route lands there (a Land waypoint), which is where Sortie expects the
// change; otherwise the operator has to add that landing.
struct BatteryChange
{
    RoutePlace at;
    double batteryLeft = 0.0;  // fraction of the battery left on arrival there (>= the reserve)
    bool planned = false;
};

struct EnduranceEstimate
{
    mission::RouteTimeline timeline;
    std::vector<LegEnergy> legs;
    double flightTimeSeconds = 0.0;
    double energyWh = 0.0;
    double batteryAtEnd = 1.0;    // 1 - energyWh / batteryWh: of one battery, negative when it is not enough
    int batteriesNeeded = 1;      // with the reserve kept on each: the changes + 1
    std::vector<BatteryChange> changes;
    double lastBatteryAtEnd = 1.0; // the fraction left on the battery flown last, at the end
    int legTooLong = 0;           // a leg (number) that alone needs more than one battery; 0: none
    // The first place along the route (on the first battery) beyond which flying straight home at
    // cruise speed and descending there no longer lands with the reserve. nullopt when home is not
    // known, or when home stays in reach all along (the route fits with its way home).
    std::optional<RoutePlace> pointOfNoReturn;
    bool homeKnown = false;

    double reserveWh = 0.0;
    double usableWh = 0.0;
    bool fitsOneBattery() const { return changes.empty() && legTooLong == 0; }
};

// The route's time and energy with a profile (whose problem() must be empty) in the conditions;
// an error when a leg cannot be flown (no speed, a wind it cannot make headway against).
mission::Result<EnduranceEstimate> estimateEndurance(const mission::Route &route, const EnergyProfile &profile,
                                                     const FlightConditions &conditions = {},
                                                     mission::ScanPlanCache *cache = nullptr);

// Energy (Wh) one timed leg uses (docs/endurance.md, "Pricing").
double legEnergyWh(const mission::TimedLeg &leg, const EnergyProfile &profile);

// Energy (Wh) to fly straight home from a position at cruise speed in the wind and then descend
// `heightAboveHome` metres (climb, when negative). nullopt when the wind does not let the vehicle
// make headway towards home. For the route's planner and the fly view's in-flight advice alike.
std::optional<double> energyHomeWh(const EnergyProfile &profile, const mission::GeoPoint &from, double heightAboveHome,
                                   const mission::GeoPoint &home, const mission::Wind &wind = {});

// The height above home of an altitude in its frame: AGL is taken as above home's ground, AMSL
// against home's AMSL altitude.
double heightAboveHome(double altitude, mission::AltitudeType type, const mission::HomePosition &home);

} // namespace sortie::endurance
