#pragma once

#include "VehicleLink.h"

namespace sortie::flightlog {

// The link of a replayed vehicle: it delivers what a log recorded, as the live links deliver what
// they receive, so the same Vehicle model (instruments, history, map) shows it. Its protocol is
// "Replay", which no live link has: a replayed vehicle can never be taken for a live one, and every
// command is refused.
class ReplayVehicleLink : public vehicle::VehicleLink
{
    Q_OBJECT

public:
    explicit ReplayVehicleLink(vehicle::VehicleIdentity recorded, QObject *parent = nullptr);

    static QString protocolName() { return QStringLiteral("Replay"); }

    void deliver(const vehicle::TelemetryBatch &batch);
    void setState(State state); // as the log says the live link was at the replay's position

    QString protocol() const override { return protocolName(); }
    vehicle::VehicleIdentity identity() const override { return m_identity; }
    State state() const override { return m_state; }
    Capabilities capabilities() const override { return {}; }
    void start() override {}
    void stop() override {}
    void arm(bool, Done done) override { refuse(done); }
    void setMode(vehicle::FlightMode, Done done) override { refuse(done); }
    void takeoff(double, Done done) override { refuse(done); }
    void land(Done done) override { refuse(done); }
    void returnHome(Done done) override { refuse(done); }
    void goTo(double, double, double, double, Done done) override { refuse(done); }
    void prepareMission(const mission::Route &, PrepareDone done) override;
    void uploadMission(const vehicle::PreparedMission &, UploadObserver, Done done) override { refuse(done); }
    void downloadMission(MissionDone done) override;
    void readParameters(ParametersDone done) override;
    void setParameter(const QString &, double, Done done) override { refuse(done); }

private:
    void refuse(const Done &done);

    vehicle::VehicleIdentity m_identity;
    State m_state = State::Connected;
};

} // namespace sortie::flightlog
