#pragma once

#include "TelemetrySample.h"

#include <QString>

namespace com::ugcs::ucs::proto {
class ObjectModificationEvent;
class RoutePass;
} // namespace com::ugcs::ucs::proto

namespace sortie::vehicle {

// Follows the UgCS server's RoutePass of one vehicle (the server's record of a route being
// executed: created on upload, updated as the vehicle advances, removed once the route is fully
// processed) and turns it into the same mission telemetry a VCI vehicle reports: MissionCurrent,
// MissionReached, MissionCount and MissionState. Pure: the HCI link feeds it events and emits what
// comes out. See docs/vehicle-model.md, "Mission progress over HCI", for the index mapping (our
// assumption about what waypointIndex counts).
class HciRoutePassTracker
{
public:
    struct Outcome
    {
        enum class Kind { Applied, Ignored, Dropped };
        Kind kind = Kind::Ignored;
        TelemetryBatch batch; // Applied: the mission fields to ingest
        QString reason;       // Dropped: why, for the log and the operator
    };

    explicit HciRoutePassTracker(int vehicleId);

    // How many waypoints the mission this client last uploaded to the vehicle has (the processed
    // route's waypoints, as Vehicle::mission() holds them); 0 when unknown.
    void setUploadedCount(int count) { m_uploadedCount = count; }

    // An object-modification event of the RoutePass subscription (any vehicle's).
    Outcome apply(const com::ugcs::ucs::proto::ObjectModificationEvent &event, int64_t timeMs);
    // A RoutePass as GetObjectList returns it (the route already in execution when the link starts).
    Outcome apply(const com::ugcs::ucs::proto::RoutePass &pass, int64_t timeMs);

private:
    Outcome update(const com::ugcs::ucs::proto::RoutePass &pass, int objectId, int64_t timeMs);
    Outcome removed(int objectId, int64_t timeMs);

    int m_vehicleId;
    int m_uploadedCount = 0;
    int m_passId = -1; // the pass followed; -1: none
    int m_active = -1; // mission index last reported
    int m_count = 0;
};

} // namespace sortie::vehicle
