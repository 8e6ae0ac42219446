#pragma once

#include "FleetConflictRule.h"  // FleetConflict, the rows' type

#include <QAbstractListModel>

#include <memory>
#include <vector>

namespace sortie::client {
class FleetRoutes;
class RoutePreparation;
} // namespace sortie::client
namespace sortie::mission {
class RouteAnalyzer;
}

namespace sortie::deconfliction {

// The open route's conflicts with the routes other vehicles hold or fly, for the views: a row per
// conflict in time order (the route panel's timeline of conflicts, by role) and both vehicles'
// positions at each closest approach (conflicts(), which the map's conflict layer draws). It
// registers FleetConflictRule on the route's analyzer, so the issue list and the upload gate judge
// the same conflicts (docs/deconfliction.md).
class RouteDeconfliction : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY conflictsChanged)
    // Separation minima (metres): closer than both is a conflict. 20 m and 15 m unless set.
    Q_PROPERTY(double horizontalSeparation READ horizontalSeparation WRITE setHorizontalSeparation NOTIFY separationChanged)
    Q_PROPERTY(double verticalSeparation READ verticalSeparation WRITE setVerticalSeparation NOTIFY separationChanged)

public:
    // A row's roles: the conflict's message (text), seconds from the start to the closest
    // approach, the separations then (metres), whether the other flies, the open route's leg then,
    // the other vehicle's name and route.
    enum Roles { TextRole = Qt::UserRole + 1, TimeRole, HorizontalRole, VerticalRole, FlyingRole, LegRole, OtherVehicleRole, OtherRouteRole };

    // None is owned; `preparation` gives the vehicle the route is for (its own routes are not others).
    RouteDeconfliction(client::FleetRoutes *routes, client::RoutePreparation *preparation, mission::RouteAnalyzer *analyzer,
                       QObject *parent = nullptr);
    ~RouteDeconfliction() override;

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

    int count() const { return int(m_ordered.size()); }
    // The conflicts, soonest first (a row each).
    const std::vector<FleetConflict> &conflicts() const { return m_ordered; }
    double horizontalSeparation() const;
    double verticalSeparation() const;
    void setHorizontalSeparation(double metres);
    void setVerticalSeparation(double metres);
    FleetConflictRule *rule() const { return m_rule.get(); }

signals:
    void conflictsChanged();
    void separationChanged();

private:
    void readConflicts();

    std::unique_ptr<FleetConflictRule> m_rule;
    std::vector<FleetConflict> m_ordered;
};

} // namespace sortie::deconfliction
