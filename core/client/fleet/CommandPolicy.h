#pragma once

#include "Vehicle.h"

#include <QObject>

namespace sortie::client {

// The rules for commanding a vehicle, in one place the views bind to: which commands ask first
// (and what they ask), the take-off altitude (the vehicle's own `takeoff_altitude` parameter when
// it reports one, else the operator's setting), and the flight modes with the names the operator
// reads. Commands are a Command, in C++ and in QML (`CommandPolicy.Arm`).
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

    static constexpr double kMinTakeoffAltitude = 2;
    static constexpr double kMaxTakeoffAltitude = 500;

signals:
    void defaultTakeoffAltitudeChanged();

private:
    double m_defaultTakeoffAltitude = 20;
};

} // namespace sortie::client
