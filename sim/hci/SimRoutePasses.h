#pragma once

#include "HciProto.h"

#include <QtGlobal>

#include <map>

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;
class SimObjectStore;
class SimVehicle;

// The server's RoutePass objects: one per vehicle that carries an uploaded route, kept in the object
// store so that clients see them through GetObjectList and object-modification events. Created on
// upload (without waypointIndex: the route is on board, not yet flown), updated each time the
// vehicle starts for another waypoint, removed once the last one is reached (the route is fully
// processed) or another route replaces it. waypointIndex counts the processed route's waypoints as
// the vehicle flies them (its waypoint, take-off and landing actions in order, across segments).
class SimRoutePasses
{
public:
    explicit SimRoutePasses(SimObjectStore &store);

    // A route was loaded into the vehicle: replaces its pass.
    void uploaded(const SimVehicle &vehicle, const pb::ProcessedRoute &route, qint64 nowMs);
    // After each tick of the vehicle's flight: publishes the waypoint it flies to, or its end.
    void follow(const SimVehicle &vehicle);
    // Removes passes left in a loaded store: a restarted server flies no route.
    void clearStale();

private:
    struct Pass
    {
        int objectId = -1;
        int waypointIndex = -1; // as last published; -1: not yet flown
        quint64 missionVersion = 0;
    };
    void remove(int vehicleId);

    SimObjectStore &m_store;
    std::map<int, Pass> m_passes; // by vehicle id
};

} // namespace sortie::sim
