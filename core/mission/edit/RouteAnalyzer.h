#pragma once

#include "RouteRule.h"
#include "RouteStatistics.h"
#include "RouteValidator.h"
#include "ScanPlanCache.h"
#include "ValidationIssueModel.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

namespace sortie::mission {

class RouteModel;

// Keeps a route's statistics and validation current. Edits only mark the results stale; one
// recomputation runs when the edits pause for `delay` ms (a drag of a waypoint emits many row
// changes, the figures are computed once). Results are plain values; the issue list is a model.
class RouteAnalyzer : public QObject
{
    Q_OBJECT
    Q_PROPERTY(double lengthMeters READ lengthMeters NOTIFY statisticsChanged)
    Q_PROPERTY(double flightTimeSeconds READ flightTimeSeconds NOTIFY statisticsChanged)
    Q_PROPERTY(int photoCount READ photoCount NOTIFY statisticsChanged)
    Q_PROPERTY(int waypointCount READ waypointCount NOTIFY statisticsChanged)
    Q_PROPERTY(int areaScanCount READ areaScanCount NOTIFY statisticsChanged)
    Q_PROPERTY(double climbMeters READ climbMeters NOTIFY statisticsChanged)
    Q_PROPERTY(double descentMeters READ descentMeters NOTIFY statisticsChanged)
    // {south, west, north, east} in degrees (west > east across the antimeridian); empty without points.
    Q_PROPERTY(int errorCount READ errorCount NOTIFY validationChanged)
    Q_PROPERTY(int warningCount READ warningCount NOTIFY validationChanged)
    Q_PROPERTY(sortie::mission::ValidationIssueModel *issues READ issues CONSTANT)
    Q_PROPERTY(bool pending READ isPending NOTIFY pendingChanged)

public:
    explicit RouteAnalyzer(const RouteModel *model, QObject *parent = nullptr);

    void setDelay(int milliseconds);
    // Runs `rule` (not owned) on every recomputation, and recomputes when it says it changed.
    void addRule(RouteRule *rule);
    const std::vector<QPointer<RouteRule>> &rules() const { return m_rules; }
    int delay() const { return m_timer.interval(); }

    const RouteStatistics &statistics() const { return m_statistics; }
    const ValidationReport &validation() const { return m_validation; }
    ValidationIssueModel *issues() const { return m_issues; }
    double lengthMeters() const { return m_statistics.lengthMeters; }
    double flightTimeSeconds() const { return m_statistics.flightTimeSeconds; }
    int photoCount() const { return m_statistics.photoCount; }
    int waypointCount() const { return m_statistics.waypointCount; }
    int areaScanCount() const { return m_statistics.areaScanCount; }
    double climbMeters() const { return m_statistics.climbMeters; }
    double descentMeters() const { return m_statistics.descentMeters; }
    int errorCount() const { return m_validation.errorCount(); }
    int warningCount() const { return m_validation.warningCount(); }
    bool isPending() const { return m_timer.isActive(); }
    int recomputeCount() const { return m_recomputes; }

    Q_INVOKABLE void recomputeNow();

signals:
    void statisticsChanged();
    void validationChanged();
    void pendingChanged();
    void recomputed();

private:
    void schedule();

    const RouteModel *m_model;
    QTimer m_timer;
    ScanPlanCache m_scans;
    RouteStatistics m_statistics;
    ValidationReport m_validation;
    ValidationIssueModel *m_issues;
    std::vector<QPointer<RouteRule>> m_rules;
    int m_recomputes = 0;
};

} // namespace sortie::mission
