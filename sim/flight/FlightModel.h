#pragma once

#include "SimBattery.h"
#include "SimPower.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sortie::sim {

// A simulated multicopter: enough physics for a ground station to watch it arm, climb, fly a route,
// hold, land and come home, and a battery drained by what that costs (its EnergyProfile, SimPower.h).
// No I/O: the HCI server and the VCI vehicles tick it and translate its state into their own
// telemetry. Angles in degrees here; protocols convert at their edge.
class FlightModel
{
public:
    enum class Mode { Manual, Hold, Takeoff, Auto, Guided, Land, ReturnHome };

    struct Waypoint
    {
        double latitude = 0;   // degrees
        double longitude = 0;  // degrees
        double altitudeAgl = 0;// metres above the home point
        double speed = 0;      // m/s; 0 means the model's cruise speed
        double acceptanceRadius = 0; // m; 0 means the model's
        double holdSeconds = 0;      // waits this long once reached
        bool landHere = false;       // lands once reached (and waited), straight down: the mission ends
    };

    struct State
    {
        double latitude = 0, longitude = 0; // degrees
        double altitudeAgl = 0;             // metres above home ground
        double floor = 0;                   // the ground under it, metres above home ground (0 without a ground)
        double groundElevation = 0;         // metres AMSL of the home ground
        double heading = 0;                 // degrees, 0 = north, clockwise
        double groundSpeed = 0, verticalSpeed = 0; // m/s, vertical positive up
        double roll = 0, pitch = 0;         // degrees
        double batteryVoltage = 0;          // volts, under the present load
        double batteryCurrent = 0;          // amperes drawn
        double batteryRemaining = 1;        // 0..1 of the energy a full battery holds
        int satellites = 0;
        int gpsFix = 0;                     // 0 none, 2 2D, 3 3D
        bool armed = false;
        Mode mode = Mode::Manual;
        int currentWaypoint = -1;           // index in the mission while flying it, else -1
        bool missionComplete = false;       // its last waypoint was reached; cleared by a new mission or start
        double homeLatitude = 0, homeLongitude = 0;
        double altitudeAmsl() const { return groundElevation + altitudeAgl; }
        bool airborne() const { return altitudeAgl - floor > 0.2; }
    };

    // Why a command was refused; empty when it was accepted.
    using Refusal = std::string;

    struct Limits
    {
        double cruiseSpeed = 8;      // m/s
        double maxSpeed = 15;        // m/s
        double climbRate = 3;        // m/s
        double descentRate = 2;      // m/s
        double yawRate = 90;         // deg/s
        double acceptanceRadius = 2; // m
        double takeoffAltitude = 20; // m AGL when none is given
        double returnAltitude = 40;  // m AGL for return-home
        // What flying costs and what the battery holds; its cruise speed and rates should be the
        // ones above (forProfile makes them so), or the sim flies other speeds than it describes.
        endurance::EnergyProfile energy = simEnergyProfile();

        // The default limits with the profile's cruise speed, climb and descent rates.
        static Limits forProfile(const endurance::EnergyProfile &profile);
    };

    FlightModel(double homeLatitude, double homeLongitude, double groundElevation);
    FlightModel(double homeLatitude, double homeLongitude, double groundElevation, Limits limits);

    // The ground under a place, metres AMSL (nullopt: unknown). Without it the ground is level at
    // home's; with it the vehicle lands on the ground under it and does not fly below it.
    using GroundFunction = std::function<std::optional<double>(double latitude, double longitude)>;
    void setGround(GroundFunction ground) { m_ground = std::move(ground); }
    // Called inside tick() when the mission's waypoint `index` is reached, once, before its wait:
    // where a vehicle runs the waypoint's actions (its camera's, for the simulator's shutter).
    using WaypointReached = std::function<void(int index)>;
    void setWaypointReached(WaypointReached reached) { m_waypointReached = std::move(reached); }

    const State &state() const { return m_state; }
    const Limits &limits() const { return m_limits; }
    const SimBattery &battery() const { return m_battery; }
    const std::vector<Waypoint> &mission() const { return m_mission; }
    uint64_t missionVersion() const { return m_missionVersion; }

    Refusal arm();
    Refusal disarm();
    Refusal takeoff(double altitudeAgl = 0);
    Refusal setMission(std::vector<Waypoint> waypoints);
    Refusal startMission();   // Auto: fly the mission from its first waypoint
    Refusal pause();          // Hold where it is
    Refusal resume();         // back to Auto from the waypoint it was flying to
    Refusal land();
    Refusal returnHome();
    Refusal goTo(double latitude, double longitude, double altitudeAgl, double speed = 0); // click-and-go
    Refusal manual();
    Refusal setMode(Mode mode); // generic entry used by protocols that set a mode by name

    // Advances the simulation by dt seconds (any step; smaller is smoother).
    void tick(double dt);

    static const char *modeName(Mode mode);
    static bool modeFromName(const std::string &name, Mode *mode);

private:
    bool flyTowards(double lat, double lon, double altAgl, double speed, double dt, double radius = 0); // true when arrived
    void climbTo(double altAgl, double dt, double timeToGo = 0); // timeToGo: seconds to the waypoint, 0 for at once
    void turnTowards(double bearing, double dt);

    void drainBattery(double dt);
    double floorHere() const; // the ground under the vehicle, metres above home's

    Limits m_limits;
    GroundFunction m_ground;
    WaypointReached m_waypointReached;
    SimBattery m_battery;
    State m_state;
    std::vector<Waypoint> m_mission;
    uint64_t m_missionVersion = 0;
    Waypoint m_target; // Guided target or Takeoff altitude
    double m_armedSeconds = 0;
    double m_holdLeft = -1; // s still to wait at the current waypoint; -1 when not waiting
    bool m_climbingOut = false; // Auto from the ground: climbing straight up before moving across
};

// Spherical-earth helpers good to a few metres over a simulated flight (the mission model has the
// WGS-84 geodesics the planner needs).
double sphericalDistance(double lat1, double lon1, double lat2, double lon2);       // metres
double sphericalBearing(double lat1, double lon1, double lat2, double lon2);        // degrees
void sphericalDestination(double lat, double lon, double bearing, double distance, double *outLat, double *outLon);

} // namespace sortie::sim
