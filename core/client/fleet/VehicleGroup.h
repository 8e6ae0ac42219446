#pragma once

#include "CommandPolicy.h"

#include <QObject>
#include <QPointer>
#include <QStringList>

#include <vector>

namespace sortie::client {

class VehicleFleet;

// The vehicles the operator has chosen to command together, and the group commands themselves: one
// confirmation that names every vehicle, then the command goes to each of them independently (a
// vehicle that refuses or is unreachable does not stop the others). Each vehicle's command and
// answer land in the fleet's command log as a single vehicle's would; `result` sums the group up
// as the answers arrive. The CommandPolicy decides the arguments (take-off altitude, mode names).
// Vehicles are named by the fleet's `vehicleId` ("HCI:7", "VCI:vci-1"); one that leaves the fleet
// leaves the group.
class VehicleGroup : public QObject
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY changed)
    Q_PROPERTY(QStringList vehicleIds READ vehicleIds NOTIFY changed)
    // The chosen vehicles' names, in the fleet's order.
    Q_PROPERTY(QStringList names READ names NOTIFY changed)
    // The last group command and each vehicle's answer so far; empty before the first.
    Q_PROPERTY(QString result READ result NOTIFY resultChanged)

public:
    VehicleGroup(VehicleFleet *fleet, const CommandPolicy *policy, QObject *parent = nullptr);

    int count() const { return int(vehicleIds().size()); }
    QStringList vehicleIds() const;
    QStringList names() const;
    QString result() const { return m_result; }

    Q_INVOKABLE bool contains(const QString &vehicleId) const { return m_chosen.contains(vehicleId); }
    Q_INVOKABLE void setChosen(const QString &vehicleId, bool chosen);
    Q_INVOKABLE void clear();

    // The one question asked before a group command: what happens, to which vehicles. Every group
    // command asks, Land and Return home too: the operator is about to move several aircraft at once.
    Q_INVOKABLE QString confirmation(sortie::client::CommandPolicy::Command command) const;
    // Sends the command to every chosen vehicle; returns how many it went to.
    Q_INVOKABLE int send(sortie::client::CommandPolicy::Command command);

signals:
    void changed();
    void resultChanged();

private:
    QString groupQuestion(CommandPolicy::Command command, int n, const QString &who) const;

    struct Answer
    {
        QString vehicle;
        bool answered = false;
        bool ok = false;
        QString message;
    };
    std::vector<vehicle::Vehicle *> chosenVehicles() const;
    void updateResult();

    QPointer<VehicleFleet> m_fleet;
    const CommandPolicy *m_policy;
    QStringList m_chosen;           // in the order chosen; vehicleIds() gives the fleet's order
    QString m_commandLabel;         // the last group command, as the result names it
    std::vector<Answer> m_answers;  // of the last group command
    std::vector<QMetaObject::Connection> m_waiting;
    QString m_result;
};

} // namespace sortie::client
