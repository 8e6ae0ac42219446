#include "CommandPolicy.h"

#include <QSettings>

#include <cmath>

namespace sortie::client {

namespace {
const QString kSettingsKey = QStringLiteral("commands/takeoffAltitude");

bool validAltitude(double metres)
{
    return std::isfinite(metres) && metres >= CommandPolicy::kMinTakeoffAltitude && metres <= CommandPolicy::kMaxTakeoffAltitude;
}

// On the ground for sure: telemetry says so and is fresh.
bool knownOnGround(const vehicle::Vehicle *v)
{
    if (!v || v->isStale(vehicle::TelemetryField::AltitudeAgl))
        return false;
    const double agl = v->altitudeAgl();
    return std::isfinite(agl) && agl < 0.5;
}
} // namespace

CommandPolicy::CommandPolicy(QObject *parent)
    : QObject(parent)
{
    const double stored = QSettings().value(kSettingsKey, m_defaultTakeoffAltitude).toDouble();
    if (validAltitude(stored))
        m_defaultTakeoffAltitude = stored;
}

void CommandPolicy::setDefaultTakeoffAltitude(double metres)
{
    if (!validAltitude(metres) || metres == m_defaultTakeoffAltitude)
        return;
    m_defaultTakeoffAltitude = metres;
    QSettings().setValue(kSettingsKey, metres);
    emit defaultTakeoffAltitudeChanged();
}

QString CommandPolicy::modeLabel(const QString &mode) const
{
    switch (vehicle::modeFromName(mode.toStdString())) {
    case vehicle::FlightMode::Manual: return tr("Manual");
    case vehicle::FlightMode::Hold: return tr("Hold");
    case vehicle::FlightMode::Takeoff: return tr("Taking off");
    case vehicle::FlightMode::Auto: return tr("Auto (fly the mission)");
    case vehicle::FlightMode::Guided: return tr("Guided");
    case vehicle::FlightMode::Land: return tr("Land");
    case vehicle::FlightMode::ReturnHome: return tr("Return home");
    case vehicle::FlightMode::Unknown: break;
    }
    return mode.isEmpty() ? tr("Unknown") : mode;
}

double CommandPolicy::takeoffAltitude(const vehicle::Vehicle *vehicle) const
{
    if (vehicle) {
        bool ok = false;
        const double own = vehicle->parameters().value(QStringLiteral("takeoff_altitude")).toDouble(&ok);
        if (ok && validAltitude(own))
            return own;
    }
    return m_defaultTakeoffAltitude;
}

bool CommandPolicy::needsConfirmation(Command command, const vehicle::Vehicle *vehicle) const
{
    switch (command) {
    case Command::Arm:
    case Command::TakeOff:
    case Command::Auto:
        return true;
    case Command::Disarm:
        return !knownOnGround(vehicle);
    case Command::Hold:
    case Command::Guided:
    case Command::Manual:
    case Command::Land:
    case Command::ReturnHome:
        return false;
    }
    return false;
}

QString CommandPolicy::confirmation(Command command, const vehicle::Vehicle *vehicle) const
{
    if (!needsConfirmation(command, vehicle))
        return {};
    const QString name = vehicle ? vehicle->name() : tr("the vehicle");
    if (command == Command::Arm)
        return tr("Arm %1? Its motors may start.").arg(name);
    if (command == Command::Disarm)
        return tr("Disarm %1? It may be in the air, and would fall.").arg(name);
    if (command == Command::TakeOff)
        return tr("Take off with %1 to %2 m above home?").arg(name).arg(takeoffAltitude(vehicle), 0, 'f', 0);
    const int count = vehicle ? int(vehicle->mission().size()) : 0;
    return count > 0 ? tr("Start the mission on %1 (%n waypoint(s))?", nullptr, count).arg(name)
                     : tr("Start the mission on %1? Sortie has not seen its mission.").arg(name);
}

QStringList CommandPolicy::blockers(Command command, const vehicle::Vehicle *vehicle) const
{
    return m_gate && vehicle ? m_gate->blockers(command, vehicle) : QStringList{};
}

QString CommandPolicy::commandLabel(Command command) const
{
    switch (command) {
    case Command::Arm: return tr("Arm");
    case Command::Disarm: return tr("Disarm");
    case Command::TakeOff: return tr("Take off");
    case Command::Auto: return tr("Auto");
    case Command::Hold: return tr("Pause");
    case Command::Guided: return tr("Guided");
    case Command::Manual: return tr("Manual");
    case Command::Land: return tr("Land");
    case Command::ReturnHome: return tr("Return home");
    }
    return {};
}

bool CommandPolicy::send(Command command, vehicle::Vehicle *vehicle) const
{
    if (!vehicle || !blockers(command, vehicle).isEmpty())
        return false;
    return dispatch(command, vehicle);
}

bool CommandPolicy::sendOverriding(Command command, vehicle::Vehicle *vehicle) const
{
    if (!vehicle)
        return false;
    const QStringList reasons = blockers(command, vehicle);
    if (!reasons.isEmpty() && vehicle->commandLog())
        vehicle->commandLog()->alert(vehicle->name(), tr("%1 sent despite the checklist (the operator overrode it): %2")
                                                          .arg(commandLabel(command), reasons.join(QStringLiteral("; "))));
    return dispatch(command, vehicle);
}

bool CommandPolicy::dispatch(Command command, vehicle::Vehicle *vehicle) const
{
    // The modes go by the names the vehicle layer knows them by (VCI's /state/mode).
    const auto switchTo = [vehicle](vehicle::FlightMode mode) {
        const std::string_view name = vehicle::modeName(mode);
        vehicle->setMode(QString::fromLatin1(name.data(), qsizetype(name.size())));
    };
    switch (command) {
    case Command::Arm: vehicle->arm(); return true;
    case Command::Disarm: vehicle->disarm(); return true;
    case Command::TakeOff: vehicle->takeoff(takeoffAltitude(vehicle)); return true;
    case Command::Auto: switchTo(vehicle::FlightMode::Auto); return true;
    case Command::Hold: switchTo(vehicle::FlightMode::Hold); return true;
    case Command::Guided: switchTo(vehicle::FlightMode::Guided); return true;
    case Command::Manual: switchTo(vehicle::FlightMode::Manual); return true;
    case Command::Land: vehicle->land(); return true;
    case Command::ReturnHome: vehicle->returnHome(); return true;
    }
    return false;
}

} // namespace sortie::client
