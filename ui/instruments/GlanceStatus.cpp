#include "GlanceStatus.h"

#include "ConnectionController.h"
#include "LanguageChange.h"
#include "TelemetryField.h"
#include "Vehicle.h"
#include "VehicleFleet.h"

#include <QLocale>

#include <algorithm>
#include <cmath>

namespace sortie::ui {

using vehicle::TelemetryField;
using vehicle::VehicleLink;

GlanceStatus::GlanceStatus(QObject *parent)
    : QObject(parent)
{
    m_status.setProperty("lowBattery", m_thresholds.lowBattery);
    m_status.setProperty("criticalBattery", m_thresholds.criticalBattery);
    connect(&m_status, &FlightStatus::changed, this, &GlanceStatus::refresh);
    i18n::onLanguageChange(this, [this] { refresh(); }); // the words are made here
    refresh();
}

GlanceStatus::~GlanceStatus() = default;

void GlanceStatus::setConnection(client::ConnectionController *connection)
{
    if (connection == m_connection)
        return;
    if (m_connection)
        disconnect(m_connection, nullptr, this, nullptr);
    m_connection = connection;
    if (m_connection) {
        connect(m_connection, &client::ConnectionController::stateChanged, this, &GlanceStatus::refresh);
        connect(m_connection, &client::ConnectionController::stateTextChanged, this, &GlanceStatus::refresh);
        connect(m_connection, &client::ConnectionController::errorChanged, this, &GlanceStatus::refresh);
    }
    emit inputsChanged();
    refresh();
}

void GlanceStatus::setFleet(client::VehicleFleet *fleet)
{
    if (fleet == m_fleet)
        return;
    if (m_fleet)
        disconnect(m_fleet, nullptr, this, nullptr);
    m_fleet = fleet;
    if (m_fleet)
        connect(m_fleet, &client::VehicleFleet::countChanged, this, &GlanceStatus::follow);
    emit inputsChanged();
    follow();
}

void GlanceStatus::setChosen(vehicle::Vehicle *vehicle)
{
    if (vehicle == m_chosen)
        return;
    m_chosen = vehicle;
    emit inputsChanged();
    follow();
}

void GlanceStatus::follow()
{
    vehicle::Vehicle *next = m_chosen ? m_chosen.data() : m_fleet && m_fleet->count() > 0 ? m_fleet->vehicleAt(0) : nullptr;
    if (next != m_vehicle) {
        if (m_vehicle)
            disconnect(m_vehicle, nullptr, this, nullptr);
        m_vehicle = next;
        if (m_vehicle) {
            connect(m_vehicle, &vehicle::Vehicle::telemetryChanged, this, &GlanceStatus::refresh);
            connect(m_vehicle, &vehicle::Vehicle::linkStateChanged, this, &GlanceStatus::refresh);
            connect(m_vehicle, &vehicle::Vehicle::staleChanged, this, &GlanceStatus::refresh);
            connect(m_vehicle, &vehicle::Vehicle::identityChanged, this, &GlanceStatus::refresh);
            connect(m_vehicle, &QObject::destroyed, this, &GlanceStatus::follow, Qt::QueuedConnection);
        }
        m_status.setVehicle(m_vehicle); // refreshes through FlightStatus::changed
    }
    refresh();
}

GlanceStatus::Level GlanceStatus::judgeConnection(const QString &state, bool failed)
{
    if (state == QLatin1String("Ready"))
        return Level::Ok;
    if (state == QLatin1String("Disconnected"))
        return failed ? Level::Problem : Level::Missing;
    if (state.isEmpty())
        return Level::Missing;
    return failed ? Level::Problem : Level::Warning; // Connecting, Authorizing, LoggingIn, Reconnecting
}

GlanceStatus::Level GlanceStatus::judgeVehicle(bool present, bool linkConnected, bool linkLost, bool stale)
{
    if (!present)
        return Level::Missing;
    if (linkLost)
        return Level::Problem;
    if (!linkConnected || stale)
        return Level::Warning;
    return Level::Ok;
}

GlanceStatus::Level GlanceStatus::judgeGps(double fixType, double satellites, const Thresholds &t)
{
    if (!std::isfinite(fixType) && !std::isfinite(satellites))
        return Level::Missing;
    if (std::isfinite(fixType) && fixType < 2)
        return Level::Problem; // no fix
    if (std::isfinite(satellites) && satellites < t.problemSatellites)
        return Level::Problem;
    if ((std::isfinite(fixType) && fixType < 3) || (std::isfinite(satellites) && satellites < t.warningSatellites))
        return Level::Warning; // a 2D fix, or few satellites
    if (!std::isfinite(fixType))
        return Level::Warning; // satellites without a fix type: not known to be a 3D fix
    return Level::Ok;
}

GlanceStatus::Level GlanceStatus::judgeBattery(FlightStatus::BatteryState state)
{
    switch (state) {
    case FlightStatus::BatteryState::Normal: return Level::Ok;
    case FlightStatus::BatteryState::Low: return Level::Warning;
    case FlightStatus::BatteryState::Critical: return Level::Problem;
    case FlightStatus::BatteryState::Unknown: break;
    }
    return Level::Missing;
}

GlanceStatus::Level GlanceStatus::judgeLink(double rate, bool linkLost, const Thresholds &t)
{
    if (linkLost)
        return Level::Problem;
    if (!std::isfinite(rate))
        return Level::Missing;
    if (rate < t.problemRate)
        return Level::Problem;
    return rate < t.okRate ? Level::Warning : Level::Ok;
}

QString GlanceStatus::batteryIconFor(double remaining)
{
    if (!std::isfinite(remaining))
        return QStringLiteral("battery-missing");
    const int tens = int(std::lround(std::clamp(remaining, 0.0, 1.0) * 10)) * 10;
    return QStringLiteral("battery-level-%1").arg(tens);
}

QString GlanceStatus::linkIconFor(double rate, bool linkLost, const Thresholds &t)
{
    if (linkLost || !std::isfinite(rate))
        return QStringLiteral("network-wireless-offline");
    if (rate < t.problemRate)
        return QStringLiteral("network-wireless-signal-none");
    if (rate < (t.problemRate + t.okRate) / 2)
        return QStringLiteral("network-wireless-signal-weak");
    if (rate < t.okRate)
        return QStringLiteral("network-wireless-signal-ok");
    return rate < 2 * t.okRate ? QStringLiteral("network-wireless-signal-good") : QStringLiteral("network-wireless-signal-excellent");
}

void GlanceStatus::refresh()
{
    const QLocale locale;
    // The connection.
    const QString state = m_connection ? m_connection->stateName() : QString();
    const bool failed = m_connection && !m_connection->errorString().isEmpty();
    m_connectionLevel = judgeConnection(state, failed);
    m_connectionText = m_connection ? m_connection->stateText() : tr("No server");

    // The vehicle.
    const vehicle::Vehicle *v = m_vehicle;
    const bool lost = v && v->linkState() == VehicleLink::State::Lost;
    m_vehicleLevel = judgeVehicle(v != nullptr, v && v->isConnected(), lost, v && v->isStale());
    m_vehicleText = v ? v->name() : tr("No vehicle");

    // Its GPS: the fix and the satellites as reported, nothing when never reported.
    const double fix = v ? v->value(TelemetryField::GpsFix) : qQNaN();
    const double satellites = v ? v->value(TelemetryField::Satellites) : qQNaN();
    m_gpsLevel = judgeGps(fix, satellites, m_thresholds);
    const QString fixName = !std::isfinite(fix) ? tr("GPS —")
                          : fix < 2            ? tr("No fix")
                          : fix < 3            ? tr("2D fix")
                          : fix < 4            ? tr("3D fix")
                          : fix < 5            ? tr("RTK float")
                                               : tr("RTK fixed");
    m_gpsText = std::isfinite(satellites) ? tr("%1, %2 sats").arg(fixName, locale.toString(int(satellites))) : fixName;

    // Its battery, against the levels (FlightStatus).
    m_batteryLevel = judgeBattery(m_status.batteryState());
    const double remaining = v ? v->batteryRemaining() : qQNaN();
    const double voltage = v ? v->batteryVoltage() : qQNaN();
    m_batteryText = std::isfinite(remaining) ? tr("%1 %").arg(locale.toString(std::lround(remaining * 100)))
                  : std::isfinite(voltage)   ? tr("%1 V").arg(locale.toString(voltage, 'f', 1))
                                             : tr("Battery —");
    m_batteryIcon = batteryIconFor(remaining);

    // Its link: how often positions come.
    const double rate = v ? m_status.telemetryRate() : qQNaN();
    m_linkLevel = judgeLink(rate, lost, m_thresholds);
    m_linkText = lost ? tr("Link lost") : std::isfinite(rate) ? tr("%1 Hz").arg(locale.toString(rate, 'f', 1)) : tr("Link —");
    m_linkIcon = linkIconFor(rate, lost, m_thresholds);
    emit changed();
}

} // namespace sortie::ui
