#pragma once

#include <QObject>
#include <QVariantList>

#include <memory>

namespace sortie::client {
class FleetRoutes;
class RoutePreparation;
} // namespace sortie::client
namespace sortie::mission {
class RouteAnalyzer;
}

namespace sortie::deconfliction {

class FleetConflictRule;

// The open route's conflicts with the routes other vehicles hold or fly, for the views: the list
// in time order (the route panel's timeline of conflicts) and both vehicles' positions at each
// closest approach (the map's conflict layer). It registers FleetConflictRule on the route's
// analyzer, so the issue list and the upload gate judge the same conflicts (docs/deconfliction.md).
class RouteDeconfliction : public QObject
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY conflictsChanged)
    // [{text, time (s from the start), horizontal, vertical, flying, leg, otherVehicle, otherRoute,
    //   latitude, longitude, altitude, otherLatitude, otherLongitude, otherAltitude}], by time.
    Q_PROPERTY(QVariantList conflicts READ conflicts NOTIFY conflictsChanged)
    // Separation minima (metres): closer than both is a conflict. 20 m and 15 m unless set.
    Q_PROPERTY(double horizontalSeparation READ horizontalSeparation WRITE setHorizontalSeparation NOTIFY separationChanged)
    Q_PROPERTY(double verticalSeparation READ verticalSeparation WRITE setVerticalSeparation NOTIFY separationChanged)

public:
    // None is owned; `preparation` gives the vehicle the route is for (its own routes are not others).
    RouteDeconfliction(client::FleetRoutes *routes, client::RoutePreparation *preparation, mission::RouteAnalyzer *analyzer,
                       QObject *parent = nullptr);
    ~RouteDeconfliction() override;

    int count() const;
    QVariantList conflicts() const;
    double horizontalSeparation() const;
    double verticalSeparation() const;
    void setHorizontalSeparation(double metres);
    void setVerticalSeparation(double metres);
    FleetConflictRule *rule() const { return m_rule.get(); }

signals:
    void conflictsChanged();
    void separationChanged();

private:
    std::unique_ptr<FleetConflictRule> m_rule;
};

} // namespace sortie::deconfliction
