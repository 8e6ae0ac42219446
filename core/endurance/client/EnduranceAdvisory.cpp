#include "EnduranceAdvisory.h"

#include "RouteEndurance.h"
#include "Vehicle.h"

#include <QLoggingCategory>

#include <cmath>
#include <QCoreApplication>

Q_LOGGING_CATEGORY(lcAdvisory, "sortie.endurance.advisory")

namespace sortie::endurance {

namespace {
std::optional<double> finite(double v)
{
    return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

QString wh(double value)
{
    return QCoreApplication::translate("EnduranceAdvisory", "%1 Wh").arg(value, 0, 'f', std::abs(value) < 10 ? 1 : 0);
}

QString percent(double fraction)
{
    return QStringLiteral("%1 %").arg(std::lround(fraction * 100));
}

// The rest of the on-board mission as a route the estimate prices: the vehicle where it is now,
// then the items from the one it flies to (all of them before it reports one). Heights are above
// home (MissionItem's frame), so every point is AGL over one home; items keep their speed (0: the
// profile's cruise speed). Actions on board are not priced (their holds are not known here).
mission::Route remainingRoute(const std::vector<vehicle::MissionItem> &items, int active, const mission::GeoPoint &from,
                              double height)
{
    mission::Route route;
    auto point = [](const mission::GeoPoint &at, double altitude, double speed) {
        mission::Waypoint w;
        w.position = at;
        w.altitude = altitude;
        w.altitudeType = mission::AltitudeType::Agl;
        w.speed = speed;
        return w;
    };
    route.segments.push_back(point(from, height, 0));
    for (size_t i = size_t(std::max(active, 0)); i < items.size(); ++i)
        route.segments.push_back(point({items[i].latitude, items[i].longitude}, items[i].altitude, items[i].speed));
    return route;
}
} // namespace

EnduranceAdvisory::EnduranceAdvisory(QObject *parent)
    : AlertList(Subject::Battery, parent)
{
    m_throttle.setSingleShot(true);
    m_throttle.setInterval(m_interval);
    connect(&m_throttle, &QTimer::timeout, this, [this] {
        if (m_pending)
            refresh();
    });
    connect(this, &EnduranceAdvisory::thresholdsChanged, this, &EnduranceAdvisory::schedule);
}

EnduranceAdvisory::~EnduranceAdvisory() = default;

vehicle::Vehicle *EnduranceAdvisory::vehicle() const
{
    return m_vehicle.data();
}

RouteEndurance *EnduranceAdvisory::endurance() const
{
    return m_endurance.data();
}

QObject *EnduranceAdvisory::vehicleObject() const
{
    return m_vehicle.data();
}

void EnduranceAdvisory::setVehicle(QObject *object)
{
    auto *v = qobject_cast<vehicle::Vehicle *>(object);
    if (v == m_vehicle)
        return;
    if (m_vehicle)
        disconnect(m_vehicle, nullptr, this, nullptr);
    m_vehicle = v;
    // Another vehicle starts afresh: its own escalations are logged.
    m_level = Level::Unknown;
    m_logged = Level::Normal;
    if (m_vehicle) {
        connect(m_vehicle, &vehicle::Vehicle::telemetryChanged, this, &EnduranceAdvisory::schedule);
        connect(m_vehicle, &vehicle::Vehicle::missionChanged, this, &EnduranceAdvisory::schedule);
        connect(m_vehicle, &QObject::destroyed, this, &EnduranceAdvisory::refresh);
    }
    emit vehicleChanged();
    refresh();
}

void EnduranceAdvisory::setEndurance(RouteEndurance *endurance)
{
    if (endurance == m_endurance)
        return;
    if (m_endurance)
        disconnect(m_endurance, nullptr, this, nullptr);
    m_endurance = endurance;
    if (m_endurance) {
        connect(m_endurance, &RouteEndurance::profileChanged, this, &EnduranceAdvisory::schedule);
        connect(m_endurance, &RouteEndurance::conditionsChanged, this, &EnduranceAdvisory::schedule);
    }
    emit enduranceChanged();
    refresh();
}

void EnduranceAdvisory::setAmberBand(double fraction)
{
    if (!(fraction >= 0 && fraction < 1) || fraction == m_amberBand)
        return;
    m_amberBand = fraction;
    emit thresholdsChanged();
}

void EnduranceAdvisory::setHysteresis(double fraction)
{
    if (!(fraction >= 0 && fraction < 1) || fraction == m_hysteresis)
        return;
    m_hysteresis = fraction;
    emit thresholdsChanged();
}

void EnduranceAdvisory::setInterval(int ms)
{
    if (ms < 0 || ms == m_interval)
        return;
    m_interval = ms;
    m_throttle.setInterval(ms);
    emit thresholdsChanged();
}

// The first change after a quiet spell is shown at once; later ones are gathered until the
// interval has passed, so pricing the rest of a long mission never runs at telemetry rate.
void EnduranceAdvisory::schedule()
{
    if (m_throttle.isActive()) {
        m_pending = true;
        return;
    }
    refresh();
}

EnduranceAdvisory::Level EnduranceAdvisory::judge(double margin, double band, double hysteresis, Level previous)
{
    if (margin <= 0)
        return Level::Red;
    if (margin <= band)
        // Out of Red only once clear of 0 by the hysteresis.
        return previous == Level::Red && margin <= hysteresis ? Level::Red : Level::Amber;
    if (previous == Level::Red && margin <= hysteresis)
        return Level::Red;
    if ((previous == Level::Amber || previous == Level::Red) && margin <= band + hysteresis)
        return Level::Amber;
    return Level::Normal;
}

void EnduranceAdvisory::clear(const QString &problem)
{
    m_left = m_home = m_reserve = m_margin = m_batteryAtEnd = std::nullopt;
    m_problem = problem;
    m_level = Level::Unknown;  // m_logged stays: a gap in the figures does not repeat the line
}

void EnduranceAdvisory::refresh()
{
    m_pending = false;
    if (m_interval > 0)
        m_throttle.start();
    const vehicle::Vehicle *v = m_vehicle;
    bool news = false;
    const std::optional<EnergyProfile> profile = m_endurance ? m_endurance->profile() : std::nullopt;
    if (!v) {
        clear(tr("No vehicle chosen"));
    } else if (!profile) {
        clear(tr("No energy profile: choose the vehicle's profile file on the mission page"));
    } else if (!std::isfinite(v->batteryRemaining())) {
        clear(tr("The vehicle reports no remaining battery"));
    } else if (!v->home().isValid()) {
        clear(tr("The vehicle reports no home"));
    } else if (!v->position().isValid()) {
        clear(tr("The vehicle reports no position"));
    } else {
        const FlightConditions conditions = m_endurance->conditions();
        const QGeoCoordinate here = v->position(), home = v->home();
        // Height above home: by AMSL altitudes where both are known, else the vehicle's AGL.
        const double height = std::isfinite(v->altitudeAmsl()) && std::isfinite(home.altitude()) ? v->altitudeAmsl() - home.altitude()
                              : std::isfinite(v->altitudeAgl())                                  ? v->altitudeAgl()
                                                                                                 : 0.0;
        const mission::GeoPoint from{here.latitude(), here.longitude()};
        m_problem.clear();
        m_left = v->batteryRemaining() * profile->batteryWh;
        m_reserve = profile->reserve * profile->batteryWh;
        m_home = endurance::energyHomeWh(*profile, from, height, {home.latitude(), home.longitude()}, conditions.wind);
        m_margin = m_home ? std::optional<double>(*m_left - *m_home - *m_reserve) : std::nullopt;

        m_batteryAtEnd.reset();
        const auto &items = v->mission();
        const int active = v->missionCurrent();
        if (items.empty()) {
            m_problem = tr("No mission on board");
        } else if (active >= int(items.size())) {
            m_batteryAtEnd = v->batteryRemaining();  // the mission is flown: what is left is left
        } else if (const auto rest = estimateEndurance(remainingRoute(items, active, from, height), *profile, conditions); rest) {
            m_batteryAtEnd = finite((*m_left - rest->energyWh) / profile->batteryWh);
        } else {
            m_problem = rest.error().message;
        }

        const Level previous = m_level == Level::Unknown ? m_logged : m_level;
        // No headway home against the wind is as bad as no energy for it.
        m_level = m_margin ? judge(*m_margin, m_amberBand * profile->batteryWh, m_hysteresis * profile->batteryWh, previous)
                           : Level::Red;
        if (!m_home)
            m_problem = tr("The vehicle cannot make headway home against the wind");
        if (m_level == Level::Normal) {
            m_logged = Level::Normal;
        } else if (m_level > m_logged && v->armed()) {
            m_logged = m_level;
            news = true;
        }
    }
    publishAdvice(news);
    emit changed();
    if (news)
        emit escalated(m_level);
}

void EnduranceAdvisory::publishAdvice(bool news)
{
    std::vector<vehicle::FlightAlert> now;
    if (m_vehicle && (m_level == Level::Amber || m_level == Level::Red)) {
        vehicle::FlightAlert alert;
        // A new level, or the same one now flying, is a new alert; whether it is news the log is
        // told of is the escalation rule's (a fall from Red to Amber is not).
        alert.key = QStringLiteral("%1|battery|%2|%3")
                        .arg(m_vehicle->id(), m_level == Level::Red ? QStringLiteral("red") : QStringLiteral("amber"),
                             m_vehicle->armed() ? QStringLiteral("armed") : QStringLiteral("disarmed"));
        alert.vehicle = m_vehicle->name();
        alert.text = advice();
        alert.severity = m_level == Level::Red ? vehicle::FlightAlert::Severity::Danger : vehicle::FlightAlert::Severity::Warning;
        now.push_back(std::move(alert));
    }
    if (news)
        qCWarning(lcAdvisory).noquote() << m_vehicle->name() << advice();
    publish(std::move(now), m_vehicle ? m_vehicle->commandLog() : nullptr, [news](const vehicle::FlightAlert &) { return news; });
}

QString EnduranceAdvisory::summary() const
{
    const QString end = m_batteryAtEnd ? percent(*m_batteryAtEnd) : QStringLiteral("—");
    const QString home = m_home ? wh(*m_home) : QStringLiteral("—");
    return tr("Battery at end of route: %1 · home needs %2").arg(end, home);
}

QString EnduranceAdvisory::advice() const
{
    if (m_level != Level::Amber && m_level != Level::Red)
        return {};
    if (!m_home)
        return tr("Battery: time to come home — no headway home against the wind");
    if (m_level == Level::Red)
        return tr("Battery: time to come home — %1 left, home needs %2: the %3 reserve is being used")
            .arg(wh(*m_left), wh(*m_home), wh(*m_reserve));
    return tr("Battery: time to come home — %1 left, home needs %2 and the reserve %3: %4 to spare")
        .arg(wh(*m_left), wh(*m_home), wh(*m_reserve), wh(*m_margin));
}

QString EnduranceAdvisory::returnHomeQuestion() const
{
    if (!m_vehicle)
        return {};
    return tr("Return %1 home now? %2").arg(m_vehicle->name(), advice());
}

} // namespace sortie::endurance
