#pragma once

#include "TelemetryField.h"
#include "TelemetrySample.h"
#include "VehicleTypes.h"

#include <QObject>
#include <QVariantMap>

#include <functional>
#include <vector>

namespace sortie::mission {
struct Route;
}

namespace sortie::vehicle {

// How the client reaches one vehicle, whatever the protocol: telemetry comes out normalised
// (TelemetryField names and units: angles in degrees, converted here at the link's edge), commands go in as calls with a result callback. Two
// implementations: VciVehicleLink (direct, over TCP or serial) and HciVehicleLink (through a UgCS
// server). Callbacks run later, never inside the call; a link drops them when destroyed.
class VehicleLink : public QObject
{
    Q_OBJECT
public:
    enum class State { Disconnected, Connecting, Connected, Lost };
    Q_ENUM(State)

    // What a link can do beyond the commands every link has.
    enum Capability {
        MissionDownload = 1 << 0, // the mission can be read back (an upload is then verified)
        Parameters = 1 << 1,
        GoTo = 1 << 2,
        Fence = 1 << 3, // the vehicle keeps a fence sent with the mission and reports its breaches (VCI)
        HomePosition = 1 << 4, // the vehicle reports its home position (VCI's home; HCI's telemetry has none)
    };
    Q_DECLARE_FLAGS(Capabilities, Capability)

    using Done = std::function<void(const CommandResult &)>;
    using MissionDone = std::function<void(const CommandResult &, const std::vector<MissionItem> &)>;
    using ParametersDone = std::function<void(const CommandResult &, const QVariantMap &)>;
    using PrepareDone = std::function<void(const CommandResult &, const PreparedMission &)>;
    // What an upload tells its caller on the way: `proceed` is asked before anything is sent (false
    // stops the upload, releasing what it holds, with CommandResult::cancel()); `step` reports each
    // stage with the server's or the link's progress (value of maximum; 0 of 0 when unknown).
    struct UploadObserver
    {
        std::function<bool()> proceed;
        std::function<void(UploadStep step, int value, int maximum)> step;
    };

    using QObject::QObject;

    virtual QString protocol() const = 0; // "VCI" or "HCI"
    virtual VehicleIdentity identity() const = 0;
    virtual State state() const = 0;
    virtual Capabilities capabilities() const = 0;

    virtual void start() = 0; // connect (if needed) and begin receiving telemetry
    virtual void stop() = 0;

    virtual void arm(bool armed, Done done) = 0;
    virtual void setMode(FlightMode mode, Done done) = 0;
    virtual void takeoff(double altitude, Done done) = 0; // m above home
    virtual void land(Done done) = 0;
    virtual void returnHome(Done done) = 0;
    // latitude and longitude in degrees, altitude m above home, speed m/s.
    virtual void goTo(double latitude, double longitude, double altitude, double speed, Done done) = 0;
    // Makes a route ready for this vehicle: HCI has the UgCS server process it against the
    // vehicle's profile; VCI expands it locally (area scans into their passes) and checks that every
    // part of it has a VCI form. Nothing is sent to the vehicle. MissionUploader is the one caller
    // that then uploads; it validates before and verifies after.
    virtual void prepareMission(const mission::Route &route, PrepareDone done) = 0;
    // The same with the fence the vehicle should keep while flying it (a link with Fence puts it in
    // the prepared mission, and uploadMission sends it first); the others prepare the route alone.
    virtual void prepareMissionWithFence(const mission::Route &route, const FenceSettings &fence, PrepareDone done)
    {
        Q_UNUSED(fence);
        prepareMission(route, std::move(done));
    }
    // Sends a prepared mission to the vehicle, inside the vehicle's lock where the protocol has one
    // (HCI). `done` comes after the lock is released; ok means the vehicle (or its server) took it.
    virtual void uploadMission(const PreparedMission &mission, UploadObserver observer, Done done) = 0;
    virtual void downloadMission(MissionDone done) = 0;
    virtual void readParameters(ParametersDone done) = 0;
    virtual void setParameter(const QString &name, double value, Done done) = 0;

signals:
    void telemetryReceived(const sortie::vehicle::TelemetryBatch &batch);
    void stateChanged(sortie::vehicle::VehicleLink::State state);
    void identityChanged(const sortie::vehicle::VehicleIdentity &identity);
    // The mission on board changed (an upload, or another station's).
    void missionChanged();
    // Something the operator should know about the link: a failed connection attempt, a lost line,
    // unreadable data. The link keeps trying; this is information, not an end.
    void errorOccurred(const QString &message);
    // Something the vehicle itself reports that the operator must see at once (a fence breach, with
    // what it did about it). The Vehicle puts it into the command log as an alert.
    void alertReported(const QString &text);
    // Where the vehicle's camera video is (UgCS's video_stream_uri), as the vehicle last said.
    void videoStreamUriReported(const QString &uri);
    // The vehicle's camera took a photo (Sortie's VCI profile reports each on /camera/photo).
    void photoTaken(const sortie::vehicle::CameraPhoto &photo);
};

} // namespace sortie::vehicle

Q_DECLARE_OPERATORS_FOR_FLAGS(sortie::vehicle::VehicleLink::Capabilities)
Q_DECLARE_METATYPE(sortie::vehicle::TelemetryBatch)
