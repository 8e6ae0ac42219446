#pragma once

#include "Vehicle.h"

#include <QObject>
#include <QStringList>

namespace sortie::client {

class CommandGate;

// The rules for commanding a vehicle, in one place the views bind to: which commands ask first
// (and what they ask), the take-off altitude (the vehicle's own `takeoff_altitude` parameter when
// it reports one, else the operator's setting), and the flight modes with the names the operator
// reads. Commands are a Command, in C++ and in QML (`CommandPolicy.Arm`). A gate handed in (the
// pre-flight checklist) holds commands back: send() refuses what it holds back, and only
// sendOverriding() sends it, writing the override to the vehicle's command log (and so the flight
// log).
class CommandPolicy : public QObject
{
    Q_OBJECT
    // The take-off altitude when the vehicle does not say, m above home (2..500; 20 by default).
    Q_PROPERTY(double defaultTakeoffAltitude READ defaultTakeoffAltitude WRITE setDefaultTakeoffAltitude NOTIFY defaultTakeoffAltitudeChanged)

public:
    // What the command bar sends. Auto, Hold, Guided and Manual switch to that flight mode (Auto
    // starts or resumes the mission, Hold pauses it); Land and ReturnHome are commands of their own.
    enum class Command { Arm, Disarm, TakeOff, Auto, Hold, Guided, Manual, Land, ReturnHome };
    Q_ENUM(Command)

    explicit CommandPolicy(QObject *parent = nullptr);

    double defaultTakeoffAltitude() const { return m_defaultTakeoffAltitude; }
    void setDefaultTakeoffAltitude(double metres);

    Q_INVOKABLE double takeoffAltitude(const sortie::vehicle::Vehicle *vehicle) const;
    // Arm, take-off and starting the mission ask; so does disarming unless the vehicle is known to
    // be on the ground. Land, hold and return home never wait for a dialog: they are what an
    // operator reaches for when something goes wrong.
    Q_INVOKABLE bool needsConfirmation(sortie::client::CommandPolicy::Command command, const sortie::vehicle::Vehicle *vehicle) const;
    // The question to ask, naming the vehicle and what will happen; empty when none is asked.
    Q_INVOKABLE QString confirmation(sortie::client::CommandPolicy::Command command, const sortie::vehicle::Vehicle *vehicle) const;
    // Sends the command with the policy's arguments (take-off altitude, the mode). False without a
    // vehicle or for a value that is not a Command.
    Q_INVOKABLE bool send(sortie::client::CommandPolicy::Command command, sortie::vehicle::Vehicle *vehicle) const;
    Q_INVOKABLE QString modeLabel(const QString &mode) const;

    // The gate asked before every command (not owned; nullptr: none). The graph hands in the
    // pre-flight checklists.
    void setGate(CommandGate *gate) { m_gate = gate; }
    CommandGate *gate() const { return m_gate; }
    // What holds the command back on the vehicle, one line per reason; empty when it may go.
    Q_INVOKABLE QStringList blockers(sortie::client::CommandPolicy::Command command, const sortie::vehicle::Vehicle *vehicle) const;
    // Sends a command the gate holds back, after the operator said so: the override and its reasons
    // go to the command log first. The same as send() when nothing holds it back.
    Q_INVOKABLE bool sendOverriding(sortie::client::CommandPolicy::Command command, sortie::vehicle::Vehicle *vehicle) const;
    // "Arm", "Take off", "Pause": the command as the group's result and the command log name it.
    Q_INVOKABLE QString commandLabel(sortie::client::CommandPolicy::Command command) const;

    static constexpr double kMinTakeoffAltitude = 2;
    static constexpr double kMaxTakeoffAltitude = 500;

signals:
    void defaultTakeoffAltitudeChanged();

private:
    bool dispatch(Command command, vehicle::Vehicle *vehicle) const;

    double m_defaultTakeoffAltitude = 20;
    CommandGate *m_gate = nullptr;
};

// What may hold a command back before it goes to a vehicle. Implemented above the client, by the
// pre-flight checklists (core/preflight/client), and handed to CommandPolicy::setGate.
class CommandGate
{
public:
    virtual ~CommandGate() = default;
    // One line per reason the command may not go to the vehicle now; empty when it may.
    virtual QStringList blockers(CommandPolicy::Command command, const vehicle::Vehicle *vehicle) = 0;
};

} // namespace sortie::client
