#include "RouteEndurance.h"

#include "EnduranceRule.h"
#include "RouteAnalyzer.h"
#include "RouteModel.h"

#include <QLoggingCategory>
#include <QSettings>

#include <cmath>
#include <QCoreApplication>

Q_LOGGING_CATEGORY(lcEndurance, "sortie.endurance")

namespace sortie::endurance {

namespace {
const QString kProfileKey = QStringLiteral("endurance/profileFile");
} // namespace

RouteEndurance::RouteEndurance(QSettings *settings, mission::RouteAnalyzer *analyzer, const mission::RouteModel *model, QObject *parent)
    : QObject(parent)
    , m_settings(settings)
    , m_analyzer(analyzer)
    , m_model(model)
    , m_rule(std::make_unique<EnduranceRule>())
{
    Q_ASSERT(settings && analyzer && model);
    analyzer->addRule(m_rule.get());
    connect(analyzer, &mission::RouteAnalyzer::recomputed, this, &RouteEndurance::refresh);
    const QString remembered = m_settings->value(kProfileKey).toString();
    if (!remembered.isEmpty() && !loadProfile(remembered))
        qCWarning(lcEndurance).noquote() << "the remembered energy profile cannot be used:" << m_problem;
    else
        refresh();
}

RouteEndurance::~RouteEndurance() = default;

bool RouteEndurance::loadProfile(const QString &path)
{
    const mission::Result<EnergyProfile> read = loadEnergyProfile(path);
    if (!read) {
        setProfile(std::nullopt);
        m_problem = read.error().toString();
        emit estimateChanged();
        return false;
    }
    setProfile(read.value(), path);
    m_settings->setValue(kProfileKey, path);
    qCInfo(lcEndurance).noquote() << "energy profile" << read->name << "from" << path;
    return true;
}

void RouteEndurance::clearProfile()
{
    m_settings->remove(kProfileKey);
    setProfile(std::nullopt);
}

void RouteEndurance::setProfile(const std::optional<EnergyProfile> &profile, const QString &path)
{
    m_profile = profile;
    m_path = profile ? path : QString();
    m_rule->setProfile(profile);  // re-runs the analyzer, which refreshes this
    emit profileChanged();
    refresh();
}

void RouteEndurance::refresh()
{
    std::optional<EnduranceEstimate> estimate;
    QString problem;
    const mission::Route &route = m_model->route();
    m_home = route.settings.home;
    if (!m_profile) {
        problem = QCoreApplication::translate("RouteEndurance", "No energy profile: choose the vehicle's profile file");
    } else if (route.segments.empty()) {
        problem = QCoreApplication::translate("RouteEndurance", "The route has no points");
    } else if (const mission::Result<EnduranceEstimate> e = estimateEndurance(route, *m_profile, m_conditions); e) {
        estimate = e.value();
    } else {
        problem = e.error().message;
    }
    m_estimate = std::move(estimate);
    m_problem = problem;
    emit estimateChanged();
}

QVariant RouteEndurance::energyHomeWh(double latitude, double longitude, double heightAboveHome) const
{
    if (!m_profile || !m_home)
        return {};
    const std::optional<double> wh = endurance::energyHomeWh(*m_profile, {latitude, longitude}, heightAboveHome, m_home->position,
                                                             m_conditions.wind);
    return wh ? QVariant(*wh) : QVariant();
}

QString RouteEndurance::profileName() const
{
    return m_profile ? m_profile->name : QString();
}

QString RouteEndurance::profileSource() const
{
    return m_profile ? sourceName(m_profile->source) : QString();
}

QVariant RouteEndurance::reserve() const
{
    return m_profile ? QVariant(m_profile->reserve) : QVariant();
}

QVariant RouteEndurance::flightTime() const
{
    return m_estimate ? QVariant(m_estimate->flightTimeSeconds) : QVariant();
}

QVariant RouteEndurance::energyWh() const
{
    return m_estimate ? QVariant(m_estimate->energyWh) : QVariant();
}

QVariant RouteEndurance::batteryAtEnd() const
{
    return m_estimate ? QVariant(m_estimate->batteryAtEnd) : QVariant();
}

QVariant RouteEndurance::batteriesNeeded() const
{
    return m_estimate ? QVariant(m_estimate->batteriesNeeded) : QVariant();
}

QVariant RouteEndurance::noReturnDistance() const
{
    return m_estimate && m_estimate->pointOfNoReturn ? QVariant(m_estimate->pointOfNoReturn->distance) : QVariant();
}

QVariant RouteEndurance::noReturnLeg() const
{
    return m_estimate && m_estimate->pointOfNoReturn ? QVariant(m_estimate->pointOfNoReturn->leg) : QVariant();
}

void RouteEndurance::setConditions(const FlightConditions &conditions)
{
    m_conditions = conditions;
    m_rule->setConditions(conditions);
    emit conditionsChanged();
    refresh();
}

void RouteEndurance::setWindSpeed(double speed)
{
    if (!(speed >= 0) || speed == m_conditions.wind.speed)
        return;
    FlightConditions c = m_conditions;
    c.wind.speed = speed;
    setConditions(c);
}

void RouteEndurance::setWindFrom(double degrees)
{
    if (!std::isfinite(degrees) || degrees == m_conditions.wind.fromDeg)
        return;
    FlightConditions c = m_conditions;
    c.wind.fromDeg = degrees;
    setConditions(c);
}

void RouteEndurance::setStopAndTurn(bool on)
{
    if (on == stopAndTurn())
        return;
    FlightConditions c = m_conditions;
    c.turns = on ? mission::TurnMode::StopAndTurn : mission::TurnMode::Coordinated;
    setConditions(c);
}

} // namespace sortie::endurance
