#include "ProximityMonitor.h"

#include "LocalTangentPlane.h"
#include "TrafficPicture.h"
#include "Vehicle.h"
#include "VehicleFleet.h"

#include <QLocale>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::deconfliction {

using vehicle::TelemetryField;
using vehicle::Vehicle;

namespace {

struct Mover
{
    QString name;
    mission::GeoPoint position;
    double altitude = 0;  // m AMSL (or pressure altitude for traffic)
    double vEast = 0, vNorth = 0, vUp = 0;
    bool barometric = false;
};

std::optional<Mover> airborne(const Vehicle &v)
{
    const bool fresh = !v.isStale(TelemetryField::Latitude) && !v.isStale(TelemetryField::AltitudeAmsl)
                       && !v.isStale(TelemetryField::GroundSpeed);
    const double agl = v.altitudeAgl(), amsl = v.altitudeAmsl(), speed = v.groundSpeed();
    if (!fresh || !v.armed() || !(agl > 1.0) || !std::isfinite(amsl) || !std::isfinite(speed) || !v.position().isValid())
        return std::nullopt;
    // Where it travels: the course over the ground, else where the nose points.
    double track = v.value(TelemetryField::Course);
    if (!std::isfinite(track) || v.isStale(TelemetryField::Course))
        track = v.heading();
    // Without either its horizontal motion is unknown: it is taken where it is (its speed still
    // counts nowhere), so only what comes towards it can raise an alert.
    const double rad = track * std::numbers::pi / 180.0;
    const double climb = v.verticalSpeed();
    Mover m;
    m.name = v.name();
    m.position = {v.position().latitude(), v.position().longitude()};
    m.altitude = amsl;
    m.vEast = std::isfinite(track) ? speed * std::sin(rad) : 0;
    m.vNorth = std::isfinite(track) ? speed * std::cos(rad) : 0;
    m.vUp = std::isfinite(climb) ? climb : 0;
    return m;
}

LocalState stateOf(const Mover &m, const mission::LocalTangentPlane &plane)
{
    const mission::PlanePoint p = plane.project(m.position);
    return {p.x, p.y, m.altitude, m.vEast, m.vNorth, m.vUp};
}

QString distanceText(double metres)
{
    const QLocale locale;
    return metres >= 1000 ? QObject::tr("%1 km").arg(locale.toString(metres / 1000.0, 'f', 1))
                          : QObject::tr("%1 m").arg(locale.toString(metres, 'f', 0));
}

} // namespace

ProximityMonitor::ProximityMonitor(client::VehicleFleet *fleet, traffic::TrafficPicture *traffic, int intervalMs, QObject *parent)
    : AlertList(Subject::Proximity, parent)
    , m_fleet(fleet)
    , m_trafficPicture(traffic)
{
    if (intervalMs > 0) {
        connect(&m_timer, &QTimer::timeout, this, &ProximityMonitor::check);
        m_timer.start(intervalMs);
    }
}

std::vector<ProximityMonitor::Alert> ProximityMonitor::predict() const
{
    std::vector<Alert> found;
    if (!m_fleet)
        return found;
    std::vector<Mover> own;
    for (int row = 0; row < m_fleet->count(); ++row) {
        if (const Vehicle *v = m_fleet->vehicleAt(row)) {
            if (auto m = airborne(*v))
                own.push_back(*m);
        }
    }
    if (own.empty())
        return found;
    const mission::LocalTangentPlane plane(own.front().position);
    const auto consider = [&found](const Mover &a, const Mover &b, const Approach &approach, bool traffic, const QString &key) {
        if (!approach.conflict)
            return;
        Alert alert;
        alert.key = key;
        alert.vehicle = a.name;
        alert.other = b.name;
        alert.traffic = traffic;
        alert.inSeconds = approach.time;
        alert.horizontal = approach.horizontal;
        alert.vertical = approach.vertical;
        const QString when = approach.time < 1 ? tr("now") : tr("in %1 s").arg(std::lround(approach.time));
        alert.text = traffic ? tr("%1 and traffic %2: closest %3, %4 across and %5 in height").arg(a.name, b.name, when, distanceText(approach.horizontal), distanceText(approach.vertical))
                             : tr("%1 and %2: closest %3, %4 across and %5 in height").arg(a.name, b.name, when, distanceText(approach.horizontal), distanceText(approach.vertical));
        found.push_back(std::move(alert));
    };

    for (size_t i = 0; i < own.size(); ++i) {
        for (size_t j = i + 1; j < own.size(); ++j) {
            const Approach a = closestApproach(stateOf(own[i], plane), stateOf(own[j], plane), m_own.horizonSeconds, m_own.separation);
            consider(own[i], own[j], a, false, own[i].name + QLatin1Char('|') + own[j].name);
        }
    }
    if (m_trafficPicture) {
        for (const traffic::TrafficAircraft &aircraft : m_trafficPicture->aircraft()) {
            const traffic::TrafficReport &s = aircraft.state;
            if (aircraft.stale || s.onGround.value_or(false) || !s.latitude || !s.longitude || !s.altitudeM)
                continue;
            Mover m;
            const QString address = traffic::TrafficPicture::addressText(s);
            m.name = s.callsign && !s.callsign->isEmpty() ? QStringLiteral("%1 (%2)").arg(*s.callsign, address) : address;
            m.position = {*s.latitude, *s.longitude};
            m.altitude = *s.altitudeM;
            m.barometric = s.altitudeReference == traffic::AltitudeReference::Barometric;
            if (const auto v = traffic::velocityOf(s)) {
                m.vEast = v->east;
                m.vNorth = v->north;
                m.vUp = v->up.value_or(0.0);
            }
            Separation separation = m_traffic.separation;
            if (m.barometric)
                separation.vertical += kBarometricMarginM;
            for (const Mover &vehicle : own) {
                const Approach a = closestApproach(stateOf(vehicle, plane), stateOf(m, plane), m_traffic.horizonSeconds, separation);
                consider(vehicle, m, a, true, vehicle.name + QStringLiteral("|traffic:") + address);
            }
        }
    }
    std::sort(found.begin(), found.end(), [](const Alert &a, const Alert &b) {
        return a.inSeconds != b.inSeconds ? a.inSeconds < b.inSeconds : a.key < b.key;
    });
    return found;
}

void ProximityMonitor::check()
{
    publish(predict(), m_fleet ? m_fleet->commandLog() : nullptr);
}

} // namespace sortie::deconfliction
