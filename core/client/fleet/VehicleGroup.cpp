#include "VehicleGroup.h"

#include "VehicleFleet.h"

namespace sortie::client {

using vehicle::Vehicle;

VehicleGroup::VehicleGroup(VehicleFleet *fleet, const CommandPolicy *policy, QObject *parent)
    : QObject(parent)
    , m_fleet(fleet)
    , m_policy(policy)
{
    // A vehicle that leaves the fleet leaves the group (HCI vehicles go when the session closes).
    const auto prune = [this] {
        const qsizetype before = m_chosen.size();
        m_chosen.removeIf([this](const QString &id) { return !m_fleet || !m_fleet->vehicle(id); });
        if (m_chosen.size() != before)
            emit changed();
    };
    connect(fleet, &QAbstractItemModel::rowsRemoved, this, prune);
    connect(fleet, &QAbstractItemModel::modelReset, this, prune);
}

QStringList VehicleGroup::vehicleIds() const
{
    QStringList ids;
    if (!m_fleet)
        return ids;
    for (int row = 0; row < m_fleet->count(); ++row) {
        const QString id = m_fleet->index(row).data(VehicleFleet::VehicleIdRole).toString();
        if (m_chosen.contains(id))
            ids.append(id);
    }
    return ids;
}

QStringList VehicleGroup::names() const
{
    QStringList list;
    for (const Vehicle *v : chosenVehicles())
        list.append(v->name());
    return list;
}

std::vector<Vehicle *> VehicleGroup::chosenVehicles() const
{
    std::vector<Vehicle *> vehicles;
    for (const QString &id : vehicleIds()) {
        if (Vehicle *v = m_fleet->vehicle(id))
            vehicles.push_back(v);
    }
    return vehicles;
}

void VehicleGroup::setChosen(const QString &vehicleId, bool chosen)
{
    if (chosen == contains(vehicleId) || (chosen && (!m_fleet || !m_fleet->vehicle(vehicleId))))
        return;
    if (chosen)
        m_chosen.append(vehicleId);
    else
        m_chosen.removeAll(vehicleId);
    emit changed();
}

void VehicleGroup::clear()
{
    if (m_chosen.isEmpty())
        return;
    m_chosen.clear();
    emit changed();
}

QString VehicleGroup::confirmation(CommandPolicy::Command command) const
{
    const std::vector<Vehicle *> vehicles = chosenVehicles();
    if (vehicles.empty())
        return {};
    const int n = int(vehicles.size());
    QStringList listed;
    for (const Vehicle *v : vehicles) {
        if (command == CommandPolicy::Command::TakeOff)
            listed.append(tr("%1 (%2 m)").arg(v->name()).arg(m_policy->takeoffAltitude(v), 0, 'f', 0));
        else if (command == CommandPolicy::Command::Auto && !v->mission().empty())
            listed.append(tr("%1 (%n waypoint(s))", nullptr, int(v->mission().size())).arg(v->name()));
        else
            listed.append(v->name());
    }
    const QString who = listed.join(QStringLiteral(", "));
    QStringList held;
    for (const Vehicle *v : vehicles)
        if (!m_policy->blockers(command, v).isEmpty())
            held.append(v->name());
    // The question, and which vehicles the checklist will hold back (each one's reasons in the result).
    const QString question = groupQuestion(command, n, who);
    return held.isEmpty() ? question : question + QLatin1Char('\n') + tr("Held back by their checklist, not sent: %1.").arg(held.join(QStringLiteral(", ")));
}

QString VehicleGroup::groupQuestion(CommandPolicy::Command command, int n, const QString &who) const
{
    switch (command) {
    case CommandPolicy::Command::Arm: return tr("Arm %n vehicle(s): %1? Their motors may start.", nullptr, n).arg(who);
    case CommandPolicy::Command::Disarm: return tr("Disarm %n vehicle(s): %1? One in the air would fall.", nullptr, n).arg(who);
    case CommandPolicy::Command::TakeOff: return tr("Take off with %n vehicle(s) to their altitudes above home: %1?", nullptr, n).arg(who);
    case CommandPolicy::Command::Auto: return tr("Start or resume the mission on %n vehicle(s): %1?", nullptr, n).arg(who);
    case CommandPolicy::Command::Hold: return tr("Pause %n vehicle(s) where they are: %1?", nullptr, n).arg(who);
    case CommandPolicy::Command::Land: return tr("Land %n vehicle(s) where they are: %1?", nullptr, n).arg(who);
    case CommandPolicy::Command::ReturnHome: return tr("Send %n vehicle(s) home: %1?", nullptr, n).arg(who);
    case CommandPolicy::Command::Guided:
    case CommandPolicy::Command::Manual: return tr("Switch %n vehicle(s) to %2: %1?", nullptr, n).arg(who, m_policy->commandLabel(command));
    }
    return {};
}

int VehicleGroup::send(CommandPolicy::Command command)
{
    for (const QMetaObject::Connection &c : m_waiting)
        disconnect(c);
    m_waiting.clear();
    m_answers.clear();
    m_commandLabel = m_policy->commandLabel(command);

    const std::vector<Vehicle *> vehicles = chosenVehicles();
    m_answers.resize(vehicles.size());
    for (size_t i = 0; i < vehicles.size(); ++i) {
        Vehicle *v = vehicles[i];
        m_answers[i].vehicle = v->name();
        // The vehicle's next answer is this command's: each vehicle runs one command at a time.
        auto connection = std::make_shared<QMetaObject::Connection>();
        *connection = connect(v, &Vehicle::commandFinished, this, [this, i, connection](const QString &, bool ok, const QString &message) {
            disconnect(*connection);
            if (i >= m_answers.size())
                return;
            m_answers[i].answered = true;
            m_answers[i].ok = ok;
            m_answers[i].message = message;
            updateResult();
        });
        m_waiting.push_back(*connection);
        if (!m_policy->send(command, v)) {
            disconnect(*connection);
            const QStringList held = m_policy->blockers(command, v);
            m_answers[i] = {v->name(), true, false, held.isEmpty() ? tr("not sent") : tr("held back by its checklist (%1)").arg(held.join(QStringLiteral("; ")))};
        }
    }
    updateResult();
    return int(vehicles.size());
}

void VehicleGroup::updateResult()
{
    QStringList parts;
    int answered = 0;
    for (const Answer &a : m_answers) {
        answered += a.answered ? 1 : 0;
        parts.append(!a.answered ? tr("%1 waiting").arg(a.vehicle)
                     : a.ok      ? tr("%1 done").arg(a.vehicle)
                                 : tr("%1 failed: %2").arg(a.vehicle, a.message));
    }
    m_result = tr("%1: %2 of %n vehicle(s) answered — %3.", nullptr, int(m_answers.size()))
                   .arg(m_commandLabel).arg(answered).arg(parts.join(QStringLiteral("; ")));
    emit resultChanged();
}

} // namespace sortie::client
