#pragma once

#include "Route.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <vector>

namespace sortie::mission {

// One difference between two versions of a route, in the operator's words. Rows are table rows,
// 1-based in the text ("WP 3", "Scan 5"): the row in the newer route, or in the older one for a
// removal.
struct RouteChange
{
    enum class Kind { Added, Removed, Moved, Altitude, Speed, Actions, Waypoint, AreaScan, Settings };
    Kind kind = Kind::Settings;
    int row = -1;        // 0-based; -1 for a route setting
    double meters = 0.0; // how far a waypoint moved (Moved only)
    QString text;        // "WP 2 moved 41 m", "altitude of WP 3 80 → 100 m", "name \"A\" → \"B\""
};

// What changed from one route to another (last saved → now, theirs → mine): segments added and
// removed by position, waypoints moved (geodesic metres), altitude, speed, actions and other
// waypoint fields changed, area scans reshaped or re-parameterised, route settings changed.
// Segments are aligned by an edit distance over the parts both routes do not share, so inserting
// one waypoint reads as one addition, not as every later waypoint changed. Where the server's
// provenance differs but the content is the same, there is no change.
class RouteDiff
{
    Q_DECLARE_TR_FUNCTIONS(RouteDiff) // its words are translated in the context "RouteDiff"

public:
    static RouteDiff compare(const Route &before, const Route &after);

    const std::vector<RouteChange> &changes() const { return m_changes; }
    bool isEmpty() const { return m_changes.empty(); }
    int count() const { return int(m_changes.size()); }
    QStringList texts() const;
    // "3 changes: WP 2 moved 41 m, WP 5 added, altitude of WP 3 80 → 100 m" (the first few, then
    // "and N more"); "No changes" when there are none.
    QString summary(int listed = 3) const;

private:
    void compareSettings(const RouteSettings &before, const RouteSettings &after);
    void compareSegments(const std::vector<Segment> &before, const std::vector<Segment> &after);
    void compareSegment(const Segment &before, const Segment &after, int row);
    void compareFields(const Segment &before, const Segment &after, int row, const QString &name);
    void add(RouteChange::Kind kind, int row, QString text, double meters = 0.0);

    std::vector<RouteChange> m_changes;
};

} // namespace sortie::mission
