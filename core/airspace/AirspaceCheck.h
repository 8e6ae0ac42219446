#pragma once

#include "FlownPath.h"
#include "Zone.h"

#include <memory>
#include <vector>

namespace sortie::airspace {

class PlaneZone;

enum class ViolationKind { InsideExclusion, OutsideInclusion };
QString violationKindName(ViolationKind kind);  // "inside-exclusion", "outside-inclusion"

// A stretch of one leg inside an exclusion zone or outside every inclusion zone.
struct AirspaceViolation
{
    int zone = -1;  // index in the zone set
    ViolationKind kind = ViolationKind::InsideExclusion;
    int leg = 1;    // numbered as FlownLeg::leg
    int row = -1;   // the route row the leg ends at
    double fromDistance = 0.0, toDistance = 0.0;  // metres along the flown path from the route's start
    // The leg's height in the zone's reference was unknown (no ground data): the stretch is
    // counted on the safe side (inside an exclusion zone, outside an inclusion zone).
    bool heightUnknown = false;
};

// A leg that stays out of a zone (or inside an inclusion zone) but comes within the buffer.
struct AirspaceWarning
{
    int zone = -1;
    int leg = 1;
    int row = -1;
    double clearance = 0.0;  // metres: the least of horizontal and vertical distance to the zone's edge
};

struct AirspaceReport
{
    int zones = 0;  // active zones checked
    int outsideWindow = 0;  // UAS geographical zones left out: they do not apply in the flight's window
    std::vector<AirspaceViolation> violations;  // by leg, then distance
    std::vector<AirspaceWarning> warnings;
};

// The zones and their geographic index (a Boost.Geometry R-tree over longitude/latitude boxes).
class ZoneSet
{
public:
    explicit ZoneSet(std::vector<Zone> zones = {});
    ~ZoneSet();
    const std::vector<Zone> &zones() const { return m_zones; }
    int activeCount() const;
    // Active zones whose box meets `box` (degrees; no antimeridian crossing).
    std::vector<int> near(const mission::GeoBox &box) const;
    const std::vector<int> &activeInclusions() const { return m_inclusions; }

private:
    struct Index;
    std::vector<Zone> m_zones;
    std::vector<int> m_inclusions;
    std::unique_ptr<Index> m_index;
};

// Checks flown paths against a zone set, every piece of every leg in 3D. It remembers each leg's
// findings: checking an edited path again checks only the legs whose shape changed (dragging a
// waypoint re-checks its two legs; a waypoint inserted or removed shifts the rest, which are
// found one place on).
class AirspaceChecker
{
public:
    explicit AirspaceChecker(std::shared_ptr<const ZoneSet> zones, double buffer = 20.0);
    ~AirspaceChecker();
    double buffer() const { return m_buffer; }
    const ZoneSet &zones() const { return *m_zones; }

    // When the flight is (UTC): UAS geographical zones count only if they apply at some moment
    // of it. None: they all count (the safe side, for a flight with no time).
    void setWindow(std::optional<ed::TimeWindow> window);
    const std::optional<ed::TimeWindow> &window() const { return m_window; }
    // Whether the set's zone `index` is checked: active, and for a geographical zone, in the window.
    bool counts(int index) const { return m_counted[size_t(index)] != 0; }

    AirspaceReport check(const FlownPath &path);
    int legsCheckedLastTime() const { return m_legsChecked; }

private:
    struct Frame;
    struct LegFindings;
    const Frame &frameFor(const FlownPath &path);
    LegFindings checkLeg(const FlownLeg &leg, const Frame &frame) const;

    std::shared_ptr<const ZoneSet> m_zones;
    double m_buffer;
    std::optional<ed::TimeWindow> m_window;
    std::vector<char> m_counted;  // per zone of the set
    std::unique_ptr<Frame> m_frame;
    std::vector<FlownLeg> m_lastLegs;
    std::vector<LegFindings> m_lastFindings;
    int m_legsChecked = 0;
};

// One-shot: the path against the zones (geographical zones in `window`, all without one).
AirspaceReport checkAirspace(const FlownPath &path, const std::vector<Zone> &zones, double buffer = 20.0,
                             const std::optional<ed::TimeWindow> &window = std::nullopt);

} // namespace sortie::airspace
