#pragma once
// What the flight-log tests share: a link the test drives by hand (a live vehicle as far as the
// recorder can tell), and synthetic flights along straight legs.
#include "CommandLog.h"
#include "FlightRecorder.h"
#include "Geodesy.h"
#include "Route.h"
#include "Vehicle.h"
#include "VehicleLink.h"

#include <QDir>
#include <QMetaObject>
#include <QSignalSpy>

#include <cmath>
#include <numbers>

namespace sortie::test {

// Degrees to radians: what the protocols send, and what a log stores for angles.
inline constexpr double kRad = std::numbers::pi / 180.0;

class ScriptedLink : public vehicle::VehicleLink
{
    Q_OBJECT
public:
    explicit ScriptedLink(QString id, QString name, QObject *parent = nullptr)
        : VehicleLink(parent)
    {
        m_identity = {id, name, QStringLiteral("multicopter"), QStringLiteral("test"), QStringLiteral("VCI")};
    }
    void send(const vehicle::TelemetryBatch &batch) { emit telemetryReceived(batch); }
    void setState(State s) { m_state = s; emit stateChanged(s); }

    QString protocol() const override { return QStringLiteral("VCI"); }
    vehicle::VehicleIdentity identity() const override { return m_identity; }
    // As a vehicle that reports neither its type nor its autopilot (null strings, as a link leaves them).
    void forgetTypeAndAutopilot() { m_identity.type = QString(); m_identity.autopilot = QString(); }
    State state() const override { return m_state; }
    Capabilities capabilities() const override { return {}; }
    void start() override {}
    void stop() override {}
    void arm(bool armed, Done done) override { later(done, armed); }
    void setMode(vehicle::FlightMode, Done done) override { later(done, true); }
    void takeoff(double, Done done) override { later(done, true); }
    void land(Done done) override { later(done, true); }
    void returnHome(Done done) override { later(done, false); }
    void goTo(double, double, double, double, Done done) override { later(done, true); }
    void prepareMission(const mission::Route &, PrepareDone done) override
    {
        QMetaObject::invokeMethod(this, [done] { done(vehicle::CommandResult::success(), {}); }, Qt::QueuedConnection);
    }
    void uploadMission(const vehicle::PreparedMission &, UploadObserver, Done done) override { later(done, true); }
    void downloadMission(MissionDone) override {}
    void readParameters(ParametersDone) override {}
    void setParameter(const QString &, double, Done done) override { later(done, true); }

private:
    void later(const Done &done, bool ok)
    {
        QMetaObject::invokeMethod(this, [done, ok] { done(ok ? vehicle::CommandResult::success() : vehicle::CommandResult::failure(QStringLiteral("refused by the test"))); },
                                  Qt::QueuedConnection);
    }
    vehicle::VehicleIdentity m_identity;
    State m_state = State::Connected;
};

// One telemetry message of a multicopter at a position, as a link delivers what HCI sends at 10 Hz
// (angles in degrees; roll and pitch a hundredth of a radian or so).
inline vehicle::TelemetryBatch telemetryAt(int64_t time, double latDeg, double lonDeg, double agl, double heading, bool armed, int mode)
{
    using F = vehicle::TelemetryField;
    return {{F::Latitude, latDeg, time}, {F::Longitude, lonDeg, time}, {F::AltitudeAmsl, 10 + agl, time},
            {F::AltitudeAgl, agl, time}, {F::Roll, (0.01 * std::sin(double(time) / 900.0)) / kRad, time},
            {F::Pitch, (-0.02 + 0.005 * std::cos(double(time) / 700.0)) / kRad, time}, {F::Heading, heading, time},
            {F::GroundSpeed, 8.0, time}, {F::VerticalSpeed, 0.0, time},
            {F::BatteryVoltage, 16.8 - double(time % 3600000) / 3600000.0, time}, {F::BatteryRemaining, 0.9, time},
            {F::GpsFix, 3, time}, {F::Satellites, 14, time}, {F::Armed, armed ? 1.0 : 0.0, time}, {F::Mode, double(mode), time}};
}

// A flight along `points` (degrees) at 8 m/s, sampled every `stepMs`, starting at `t0`; an offset
// (metres, to the east of the track) makes a vehicle fly beside the line.
struct FlightSample
{
    int64_t time;
    double lat, lon, heading;
};

inline std::vector<FlightSample> flyAlong(const std::vector<mission::GeoPoint> &points, int64_t t0, int stepMs, double offsetEast = 0)
{
    std::vector<FlightSample> out;
    int64_t t = t0;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        const auto inv = mission::geodesicInverse(points[i], points[i + 1]);
        const double length = inv ? inv->distance : 0;
        const double azimuth = inv ? inv->azimuth1Deg : 0;
        const int steps = std::max(1, int(length / (8.0 * stepMs / 1000.0)));
        for (int k = 0; k < steps; ++k) {
            const auto p = mission::geodesicDirect(points[i], azimuth, length * k / steps);
            auto q = p.point;
            if (offsetEast != 0)
                q = mission::geodesicDirect(q, 90, offsetEast).point;
            out.push_back({t, q.latitude, q.longitude, azimuth});
            t += stepMs;
        }
    }
    out.push_back({t, points.back().latitude, points.back().longitude, 0});
    return out;
}

inline mission::Route routeThrough(const std::vector<mission::GeoPoint> &points, double agl, const QString &name)
{
    mission::Route route;
    route.settings.name = name;
    for (const mission::GeoPoint &p : points) {
        mission::Waypoint w;
        w.position = p;
        w.altitude = agl;
        w.altitudeType = mission::AltitudeType::Agl;
        w.speed = 8;
        route.segments.push_back(w);
    }
    return route;
}

inline const std::vector<mission::GeoPoint> kLegs = {{56.9500, 24.1000}, {56.9510, 24.1000}, {56.9510, 24.1020}, {56.9500, 24.1020}};
inline constexpr int64_t kT0 = 1'780'000'000'000;

// Records two vehicles flying the legs (the second 12 m to the east) with events along the way.
inline QString recordTwoFlights(const QString &folder, std::vector<FlightSample> *flown = nullptr)
{
    const QString path = QDir(folder).filePath(QStringLiteral("two.sortielog"));
    ScriptedLink linkA(QStringLiteral("7"), QStringLiteral("EMU-101")), linkB(QStringLiteral("8"), QStringLiteral("EMU-102"));
    vehicle::Vehicle a(&linkA), b(&linkB);
    // The recorder takes the commands from the log the vehicles write to, as a fleet's do.
    vehicle::CommandLog commands;
    a.setCommandLog(&commands);
    b.setCommandLog(&commands);
    flightlog::FlightRecorder recorder({path, {}, 100});
    QString error;
    if (!recorder.start(&error))
        qFatal("%s", qPrintable(error));
    recorder.addVehicle(&a);
    recorder.addVehicle(&b);
    recorder.followCommands(&commands);
    a.setMission({{kLegs[0].latitude, kLegs[0].longitude, 20, 8, 0, {}}, {kLegs[1].latitude, kLegs[1].longitude, 20, 8, 0, {}}});
    const auto pathA = flyAlong(kLegs, kT0, 100);
    const auto pathB = flyAlong(kLegs, kT0, 100, 12);
    if (flown)
        *flown = pathA;
    for (size_t i = 0; i < pathA.size(); ++i) {
        const int mode = i < 5 ? 1 : 4; // manual, then auto
        linkA.send(test::telemetryAt(pathA[i].time, pathA[i].lat, pathA[i].lon, 20, pathA[i].heading, i >= 3, mode));
        if (i < pathB.size())
            linkB.send(test::telemetryAt(pathB[i].time, pathB[i].lat, pathB[i].lon, 20, pathB[i].heading, i >= 3, mode));
        if (i == 40)
            linkB.setState(vehicle::VehicleLink::State::Lost);
        if (i == 60)
            linkB.setState(vehicle::VehicleLink::State::Connected);
        if (i % 200 == 0)
            recorder.flush();
    }
    a.arm();
    QSignalSpy done(&a, &vehicle::Vehicle::commandFinished);
    done.wait(5000);
    b.returnHome(); // refused by the scripted link
    QSignalSpy refused(&b, &vehicle::Vehicle::commandFinished);
    refused.wait(5000);
    recorder.stop();
    return path;
}

} // namespace sortie::test
