#include "FlightStatus.h"

#include "LanguageChange.h"
#include "Vehicle.h"

#include <cmath>

namespace sortie::ui {

using vehicle::TelemetryField;

namespace {
constexpr int64_t kRateWindowMs = 5000;

// Seconds since the vehicle was armed, by its own clock: from the first sample of the latest
// run of "armed" to the newest telemetry. NaN while disarmed or never heard.
double armedFor(const vehicle::Vehicle &v)
{
    const auto &armed = v.history().series(TelemetryField::Armed);
    if (armed.empty() || armed.newest().value == 0)
        return qQNaN();
    size_t first = armed.size() - 1;
    while (first > 0 && armed.at(first - 1).value != 0)
        --first;
    int64_t newest = armed.newest().time;
    for (TelemetryField f : {TelemetryField::Latitude, TelemetryField::AltitudeAgl, TelemetryField::BatteryVoltage})
        if (const auto last = v.history().last(f))
            newest = std::max<int64_t>(newest, last->time);
    return double(newest - armed.at(first).time) / 1000.0;
}

// The first sample of the latest run of "armed", or -1.
int64_t armedSince(const vehicle::Vehicle &v)
{
    const auto &armed = v.history().series(TelemetryField::Armed);
    size_t last = armed.size();
    while (last > 0 && armed.at(last - 1).value == 0)
        --last;
    if (last == 0)
        return -1;
    size_t first = last - 1;
    while (first > 0 && armed.at(first - 1).value != 0)
        --first;
    return armed.at(first).time;
}

double positionRate(const vehicle::Vehicle &v)
{
    const auto &series = v.history().series(TelemetryField::Latitude);
    if (series.empty())
        return qQNaN();
    const int64_t newest = series.newest().time;
    const size_t from = series.lowerBound(newest - kRateWindowMs);
    const double span = double(newest - series.at(from).time) / 1000.0;
    const size_t samples = series.size() - from;
    if (samples < 2 || span <= 0)
        return qQNaN();
    return double(samples - 1) / span;
}
} // namespace

QGeoCoordinate FlightStatus::homeOf(const vehicle::Vehicle &v)
{
    if (v.home().isValid())
        return v.home();
    const int64_t since = armedSince(v);
    if (since < 0)
        return {};
    const auto &lat = v.history().series(TelemetryField::Latitude);
    const auto &lon = v.history().series(TelemetryField::Longitude);
    const size_t i = lat.lowerBound(since), j = lon.lowerBound(since);
    if (i >= lat.size() || j >= lon.size())
        return {};
    return QGeoCoordinate(lat.at(i).value, lon.at(j).value);
}

FlightStatus::FlightStatus(QObject *parent)
    : QObject(parent)
{
    connect(this, &FlightStatus::levelsChanged, this, &FlightStatus::refresh);
    i18n::onLanguageChange(this, [this] { emit changed(); }); // progressText is worded as read
}

QObject *FlightStatus::vehicleObject() const
{
    return m_vehicle.data();
}

void FlightStatus::setVehicle(QObject *object)
{
    auto *v = qobject_cast<vehicle::Vehicle *>(object);
    if (v == m_vehicle)
        return;
    if (m_vehicle)
        disconnect(m_vehicle, nullptr, this, nullptr);
    m_vehicle = v;
    if (m_vehicle) {
        // Its flight time and telemetry rate come from the history: they move with every sample.
        connect(m_vehicle, &vehicle::Vehicle::historyChanged, this, &FlightStatus::refresh);
        connect(m_vehicle, &vehicle::Vehicle::missionChanged, this, &FlightStatus::refresh);
        connect(m_vehicle, &QObject::destroyed, this, &FlightStatus::refresh);
    }
    emit vehicleChanged();
    refresh();
}

FlightStatus::BatteryState FlightStatus::judgeBattery(double remaining, double voltage, double low, double critical,
                                                      double lowVoltage, double criticalVoltage)
{
    if (std::isfinite(remaining))
        return remaining <= critical ? BatteryState::Critical : remaining <= low ? BatteryState::Low : BatteryState::Normal;
    if (std::isfinite(voltage) && std::isfinite(lowVoltage)) {
        if (std::isfinite(criticalVoltage) && voltage <= criticalVoltage)
            return BatteryState::Critical;
        return voltage <= lowVoltage ? BatteryState::Low : BatteryState::Normal;
    }
    return BatteryState::Unknown;
}

void FlightStatus::refresh()
{
    const vehicle::Vehicle *v = m_vehicle;
    if (!v) {
        m_progress = {};
        m_complete = false;
        m_home = {};
        m_distanceToHome = m_bearingToHome = m_flightSeconds = m_telemetryRate = m_roll = m_pitch = qQNaN();
        m_battery = BatteryState::Unknown;
        emit changed();
        return;
    }
    const QGeoCoordinate position = v->position();
    m_roll = v->value(TelemetryField::Roll);
    m_pitch = v->value(TelemetryField::Pitch);
    // The mission as uploaded when known; its length as the vehicle reports it otherwise.
    m_progress = vehicle::MissionProgress::compute(v->mission(), v->missionCurrent(), position, v->groundSpeed());
    if (m_progress.count == 0)
        m_progress.count = v->missionCount();
    m_complete = m_progress.isComplete() || v->missionState() == QLatin1String("complete");
    const QGeoCoordinate home = homeOf(*v);
    m_home = home;
    m_distanceToHome = position.isValid() && home.isValid() ? position.distanceTo(home) : qQNaN();
    m_bearingToHome = vehicle::bearingBetween(position, home);
    m_flightSeconds = armedFor(*v);
    m_telemetryRate = positionRate(*v);
    m_battery = judgeBattery(v->batteryRemaining(), v->batteryVoltage(), m_lowBattery, m_criticalBattery, m_lowVoltage,
                             m_criticalVoltage);
    emit changed();
}

QString FlightStatus::progressText() const
{
    if (m_complete)
        return tr("mission complete");
    if (m_progress.isFlying())
        return tr("waypoint %1 of %2").arg(m_progress.active + 1).arg(m_progress.count);
    if (m_progress.count > 0)
        return m_progress.count == 1 ? tr("1 waypoint on board") : tr("%1 waypoints on board").arg(m_progress.count);
    return tr("no mission on board");
}

} // namespace sortie::ui
