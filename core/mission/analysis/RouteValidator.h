#pragma once

#include "Route.h"

#include <QString>

#include <vector>

namespace sortie::mission {

class ScanPlanCache;

enum class Severity { Warning, Error };

// One finding. rule is a stable identifier (see docs/missions.md); segment is the 0-based row of
// the offending waypoint or scan, -1 for the route as a whole.
struct ValidationIssue
{
    Severity severity = Severity::Error;
    QString rule;
    QString message;
    int segment = -1;
    bool operator==(const ValidationIssue &) const = default;
};

struct ValidationReport
{
    std::vector<ValidationIssue> issues;  // in row order, route-level issues first

    int errorCount() const;
    int warningCount() const;
    bool hasErrors() const { return errorCount() > 0; }
    bool operator==(const ValidationReport &) const = default;
};

// Every rule: too few points, invalid positions, altitude above the route maximum or below its
// safe altitude, AMSL altitudes that cannot be checked, non-positive speed or speed above the
// vehicle's limit, consecutive duplicates, mixed altitude types, and area scans that cross
// themselves, yield no transects or cannot be planned.
ValidationReport validateRoute(const Route &route, ScanPlanCache *cache = nullptr);

// "Waypoint 12" or "Area scan 4" (1-based row numbers, as the table shows them).
QString segmentLabel(const Route &route, int row);

} // namespace sortie::mission
