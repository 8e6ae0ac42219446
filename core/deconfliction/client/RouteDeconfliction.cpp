#include "RouteDeconfliction.h"

#include "FleetConflictRule.h"
#include "RouteAnalyzer.h"

#include <algorithm>
#include <cmath>

namespace sortie::deconfliction {

RouteDeconfliction::RouteDeconfliction(client::FleetRoutes *routes, client::RoutePreparation *preparation,
                                       mission::RouteAnalyzer *analyzer, QObject *parent)
    : QObject(parent)
    , m_rule(std::make_unique<FleetConflictRule>(routes, preparation))
{
    Q_ASSERT(routes && analyzer);
    analyzer->addRule(m_rule.get());
    connect(m_rule.get(), &FleetConflictRule::conflictsChanged, this, &RouteDeconfliction::conflictsChanged);
}

RouteDeconfliction::~RouteDeconfliction() = default;

int RouteDeconfliction::count() const
{
    return int(m_rule->conflicts().size());
}

QVariantList RouteDeconfliction::conflicts() const
{
    std::vector<const FleetConflict *> ordered;
    for (const FleetConflict &c : m_rule->conflicts())
        ordered.push_back(&c);
    std::stable_sort(ordered.begin(), ordered.end(), [](const FleetConflict *a, const FleetConflict *b) { return a->conflict.time < b->conflict.time; });
    QVariantList list;
    for (const FleetConflict *c : ordered) {
        const Conflict &k = c->conflict;
        list.append(QVariantMap{
            {QStringLiteral("text"), c->message},
            {QStringLiteral("time"), k.time},
            {QStringLiteral("horizontal"), k.horizontal},
            {QStringLiteral("vertical"), k.vertical},
            {QStringLiteral("flying"), c->otherFlying},
            {QStringLiteral("leg"), k.firstAt.leg},
            {QStringLiteral("otherVehicle"), c->otherName},
            {QStringLiteral("otherRoute"), c->otherRoute},
            {QStringLiteral("latitude"), k.firstAt.position.latitude},
            {QStringLiteral("longitude"), k.firstAt.position.longitude},
            {QStringLiteral("altitude"), k.firstAt.altitude},
            {QStringLiteral("otherLatitude"), k.secondAt.position.latitude},
            {QStringLiteral("otherLongitude"), k.secondAt.position.longitude},
            {QStringLiteral("otherAltitude"), k.secondAt.altitude},
        });
    }
    return list;
}

double RouteDeconfliction::horizontalSeparation() const
{
    return m_rule->separation().horizontal;
}

double RouteDeconfliction::verticalSeparation() const
{
    return m_rule->separation().vertical;
}

void RouteDeconfliction::setHorizontalSeparation(double metres)
{
    if (!(metres > 0) || !std::isfinite(metres) || metres == horizontalSeparation())
        return;
    Separation s = m_rule->separation();
    s.horizontal = metres;
    m_rule->setSeparation(s);
    emit separationChanged();
}

void RouteDeconfliction::setVerticalSeparation(double metres)
{
    if (!(metres > 0) || !std::isfinite(metres) || metres == verticalSeparation())
        return;
    Separation s = m_rule->separation();
    s.vertical = metres;
    m_rule->setSeparation(s);
    emit separationChanged();
}

} // namespace sortie::deconfliction
