#pragma once

#include "ConflictSearch.h"
#include "RouteRule.h"

#include <QPointer>
#include <QTimer>

#include <vector>

namespace sortie::client {
class FleetRoutes;
class RoutePreparation;
} // namespace sortie::client

namespace sortie::deconfliction {

// A conflict of the open route with a route another vehicle holds, as the views show it.
struct FleetConflict
{
    Conflict conflict;      // flight 0 is the open route, `second` the other
    QString otherVehicle;   // its vehicleId and name
    QString otherName;
    QString otherRoute;
    bool otherFlying = false;
    bool framesDiffer = false;  // heights not comparable: judged across only
    QString message;
};

// The 4D deconfliction of the open route before upload, as a validation rule (so the issue list,
// the save gate and the upload gate see it): the route, flown from now by the time model with its
// own speeds and rates, against every route another vehicle of the fleet is flying (from where
// it is along it now) or holds uploaded (assumed to start now too: the worst case, since Sortie
// cannot know when the operator starts it). A conflict with a flying vehicle is an error
// ("deconfliction-flying": the upload is refused); with an uploaded one a warning
// ("deconfliction-uploaded"). The chosen vehicle's own routes are not others. Routes whose heights
// are in different frames (AGL and AMSL, say) are compared across only, and the issue says so.
// Runs again when a route is uploaded, starts or stops flying, and every few seconds while one
// flies (its progress moves).
class FleetConflictRule : public mission::RouteRule
{
    Q_OBJECT

public:
    // Neither is owned; `preparation` may be nullptr (no chosen vehicle: every vehicle is another).
    FleetConflictRule(client::FleetRoutes *routes, client::RoutePreparation *preparation, QObject *parent = nullptr);

    void setSeparation(const Separation &separation);
    const Separation &separation() const { return m_separation; }
    void check(const mission::Route &route, mission::ScanPlanCache *cache, std::vector<mission::ValidationIssue> &issues) override;
    // What the last check found, for the views.
    const std::vector<FleetConflict> &conflicts() const { return m_conflicts; }

signals:
    void conflictsChanged();

private:
    void watchFlying();

    QPointer<client::FleetRoutes> m_routes;
    QPointer<client::RoutePreparation> m_preparation;
    Separation m_separation;
    std::vector<FleetConflict> m_conflicts;
    QTimer m_progress;  // while a route flies
};

} // namespace sortie::deconfliction
