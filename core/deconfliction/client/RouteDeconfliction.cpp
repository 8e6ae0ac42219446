#include "RouteDeconfliction.h"

#include "FleetConflictRule.h"
#include "RouteAnalyzer.h"

#include <algorithm>
#include <cmath>

namespace sortie::deconfliction {

RouteDeconfliction::RouteDeconfliction(client::FleetRoutes *routes, client::RoutePreparation *preparation,
                                       mission::RouteAnalyzer *analyzer, QObject *parent)
    : QAbstractListModel(parent)
    , m_rule(std::make_unique<FleetConflictRule>(routes, preparation))
{
    Q_ASSERT(routes && analyzer);
    analyzer->addRule(m_rule.get());
    connect(m_rule.get(), &FleetConflictRule::conflictsChanged, this, &RouteDeconfliction::readConflicts);
    readConflicts();
}

RouteDeconfliction::~RouteDeconfliction() = default;

void RouteDeconfliction::readConflicts()
{
    beginResetModel();
    m_ordered = m_rule->conflicts();
    std::stable_sort(m_ordered.begin(), m_ordered.end(),
                     [](const FleetConflict &a, const FleetConflict &b) { return a.conflict.time < b.conflict.time; });
    endResetModel();
    emit conflictsChanged();
}

int RouteDeconfliction::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QHash<int, QByteArray> RouteDeconfliction::roleNames() const
{
    return {{TextRole, "text"}, {TimeRole, "time"}, {HorizontalRole, "horizontal"}, {VerticalRole, "vertical"},
            {FlyingRole, "flying"}, {LegRole, "leg"}, {OtherVehicleRole, "otherVehicle"}, {OtherRouteRole, "otherRoute"}};
}

QVariant RouteDeconfliction::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const FleetConflict &c = m_ordered[size_t(index.row())];
    switch (role) {
    case TextRole:
    case Qt::DisplayRole: return c.message;
    case TimeRole: return c.conflict.time;
    case HorizontalRole: return c.conflict.horizontal;
    case VerticalRole: return c.conflict.vertical;
    case FlyingRole: return c.otherFlying;
    case LegRole: return c.conflict.firstAt.leg;
    case OtherVehicleRole: return c.otherName;
    case OtherRouteRole: return c.otherRoute;
    default: return {};
    }
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
