#include "ZoneAlertMonitor.h"

#include "ElevationService.h"
#include "PlaneZone.h"
#include "Vehicle.h"
#include "VehicleFleet.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::airspace {

using vehicle::TelemetryField;
using vehicle::Vehicle;

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

// An airborne vehicle as the prediction needs it.
struct ZoneAlertMonitor::Mover
{
    QString id, name;
    GeoPoint position;
    double amsl = 0, aboveHome = kNaN; // m
    double vEast = 0, vNorth = 0, vUp = 0;
};

namespace {

// Airborne as ProximityMonitor has it: armed, more than 1 m above home, with a fresh position,
// AMSL altitude and ground speed.
bool airborne(const Vehicle &v)
{
    const bool fresh = !v.isStale(TelemetryField::Latitude) && !v.isStale(TelemetryField::AltitudeAmsl)
                       && !v.isStale(TelemetryField::GroundSpeed);
    return fresh && v.armed() && v.altitudeAgl() > 1.0 && std::isfinite(v.altitudeAmsl()) && std::isfinite(v.groundSpeed())
           && v.position().isValid();
}

QString whenText(double seconds)
{
    return seconds < 1 ? QString() : QObject::tr(" in %1 s").arg(std::lround(seconds));
}

} // namespace

ZoneAlertMonitor::ZoneAlertMonitor(client::VehicleFleet *fleet, terrain::ElevationService *ground, int intervalMs, QObject *parent)
    : AlertList(Subject::Airspace, parent)
    , m_fleet(fleet)
    , m_ground(ground)
{
    if (intervalMs > 0) {
        connect(&m_timer, &QTimer::timeout, this, &ZoneAlertMonitor::check);
        m_timer.start(intervalMs);
    }
}

ZoneAlertMonitor::~ZoneAlertMonitor() = default;

void ZoneAlertMonitor::setClock(std::function<QDateTime()> clock)
{
    m_clock = std::move(clock);
}

void ZoneAlertMonitor::setZones(std::shared_ptr<const ZoneSet> zones)
{
    m_zones = std::move(zones);
}

void ZoneAlertMonitor::setVehicleZones(const QString &vehicleId, std::vector<Zone> zones)
{
    if (zones.empty())
        m_vehicleZones.remove(vehicleId);
    else
        m_vehicleZones.insert(vehicleId, std::make_shared<const ZoneSet>(std::move(zones)));
}

void ZoneAlertMonitor::predictAgainst(const Mover &m, const ZoneSet &zones, const QString &set, std::vector<Alert> &found) const
{
    if (zones.activeCount() == 0)
        return;
    // The straight line flown in the next kClearSeconds, on the plane tangent at the vehicle.
    const mission::LocalTangentPlane plane(m.position);
    const auto point = [&](double t) {
        FlownPoint p;
        p.at = {m.vEast * t, m.vNorth * t};
        p.position = t == 0 ? m.position : plane.unproject(p.at);
        p.along = std::hypot(p.at.x, p.at.y);
        const double amsl = m.amsl + m.vUp * t;
        p.height[size_t(HeightReference::Amsl)] = amsl;
        p.height[size_t(HeightReference::AboveHome)] = m.aboveHome + m.vUp * t;
        if (m_ground)
            if (const auto g = m_ground->groundAt(p.position))
                p.height[size_t(HeightReference::AboveTerrain)] = amsl - *g;
        return p;
    };
    const FlownPoint a = point(0), b = point(kClearSeconds);
    const auto keyOf = [&](const QString &zone, const char *what) { return QStringLiteral("%1|%2|%3|%4").arg(m.id, set, zone, QLatin1String(what)); };
    const auto within = [&](const QString &key, double seconds) {
        const bool raised = std::any_of(alerts().begin(), alerts().end(), [&](const Alert &x) { return x.key == key; });
        return seconds <= (raised ? kClearSeconds : kHorizonSeconds);
    };

    const QDateTime now = m_clock ? m_clock() : QDateTime::currentDateTimeUtc();
    const ed::TimeWindow window{now, now.addMSecs(qint64(kClearSeconds * 1000))};
    mission::GeoBox box{std::min(a.position.latitude, b.position.latitude), std::min(a.position.longitude, b.position.longitude),
                        std::max(a.position.latitude, b.position.latitude), std::max(a.position.longitude, b.position.longitude), false};
    for (int index : zones.near(box)) {
        const Zone &zone = zones.zones()[size_t(index)];
        if (zone.kind != ZoneKind::Exclusion)
            continue;
        if (zone.geoZone && (zone.geoZone->restriction == ed::Restriction::NoRestriction || !zone.geoZone->appliesDuring(window)))
            continue;
        const std::vector<Span> inside = PlaneZone(zone, index, plane).inside(a, b);
        if (inside.empty())
            continue;
        Alert alert;
        alert.key = keyOf(zone.name, "enter");
        alert.inSeconds = inside.front().from * kClearSeconds;
        if (!within(alert.key, alert.inSeconds))
            continue;
        alert.vehicle = m.name;
        alert.zone = zone.name;
        alert.kind = Kind::EntersExclusion;
        alert.heightUnknown = inside.front().heightUnknown;
        alert.text = alert.inSeconds < 1 ? tr("%1 is inside '%2'").arg(m.name, zone.name)
                                         : tr("%1 enters '%2'%3").arg(m.name, zone.name, whenText(alert.inSeconds));
        found.push_back(std::move(alert));
    }

    // The permitted area: the union of the set's inclusion zones (a stretch whose height is unknown
    // counts as outside).
    const std::vector<int> &inclusions = zones.activeInclusions();
    if (inclusions.empty())
        return;
    std::vector<Span> permitted;
    bool unknown = false;
    int current = -1;
    for (int index : inclusions) {
        for (const Span &s : PlaneZone(zones.zones()[size_t(index)], index, plane).inside(a, b)) {
            if (s.heightUnknown) {
                unknown = true;
                continue;
            }
            if (s.from == 0 && current < 0)
                current = index;
            permitted.push_back(s);
        }
    }
    std::sort(permitted.begin(), permitted.end(), [](const Span &x, const Span &y) { return x.from < y.from; });
    const std::vector<Span> outside = complementSpans(joinSpans(permitted));
    if (outside.empty())
        return;
    const Zone &zone = zones.zones()[size_t(current >= 0 ? current : inclusions.front())];
    Alert alert;
    alert.key = keyOf(zone.name, "leave");
    alert.inSeconds = outside.front().from * kClearSeconds;
    if (!within(alert.key, alert.inSeconds))
        return;
    alert.vehicle = m.name;
    alert.zone = zone.name;
    alert.kind = Kind::LeavesInclusion;
    alert.heightUnknown = unknown;
    alert.text = alert.inSeconds < 1 ? tr("%1 is outside '%2'").arg(m.name, zone.name)
                                     : tr("%1 leaves '%2'%3").arg(m.name, zone.name, whenText(alert.inSeconds));
    found.push_back(std::move(alert));
}

std::vector<ZoneAlertMonitor::Alert> ZoneAlertMonitor::predict() const
{
    std::vector<Alert> found;
    if (!m_fleet)
        return found;
    for (int row = 0; row < m_fleet->count(); ++row) {
        const Vehicle *v = m_fleet->vehicleAt(row);
        const auto own = v ? m_vehicleZones.find(v->id()) : m_vehicleZones.end();
        if (!v || ((!m_zones || m_zones->activeCount() == 0) && own == m_vehicleZones.end()) || !airborne(*v))
            continue;
        Mover m;
        m.id = v->id();
        m.name = v->name();
        m.position = {v->position().latitude(), v->position().longitude()};
        m.amsl = v->altitudeAmsl();
        const double home = v->value(TelemetryField::HomeAltitudeAmsl);
        m.aboveHome = std::isfinite(home) ? m.amsl - home : v->altitudeAgl();
        // Where it travels: the course over the ground, else where the nose points; neither: in place.
        double track = v->value(TelemetryField::Course);
        if (!std::isfinite(track) || v->isStale(TelemetryField::Course))
            track = v->heading();
        const double rad = track * std::numbers::pi / 180.0;
        m.vEast = std::isfinite(track) ? v->groundSpeed() * std::sin(rad) : 0;
        m.vNorth = std::isfinite(track) ? v->groundSpeed() * std::cos(rad) : 0;
        m.vUp = std::isfinite(v->verticalSpeed()) ? v->verticalSpeed() : 0;
        if (m_zones)
            predictAgainst(m, *m_zones, QStringLiteral("airspace"), found);
        if (own != m_vehicleZones.end())
            predictAgainst(m, **own, QStringLiteral("fence"), found);
    }
    for (Alert &a : found)
        if (a.heightUnknown)
            a.text += tr(" (its height there is unknown)");
    std::sort(found.begin(), found.end(), [](const Alert &x, const Alert &y) {
        return x.inSeconds != y.inSeconds ? x.inSeconds < y.inSeconds : x.key < y.key;
    });
    return found;
}

void ZoneAlertMonitor::check()
{
    publish(predict(), m_fleet ? m_fleet->commandLog() : nullptr);
}

} // namespace sortie::airspace
