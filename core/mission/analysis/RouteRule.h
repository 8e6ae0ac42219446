#pragma once

#include "RouteValidator.h"

#include <QObject>

namespace sortie::mission {

class ScanPlanCache;

// A validation rule from a library core/mission must not depend on (terrain). RouteAnalyzer runs
// every added rule after validateRoute's own and merges the issues in row order. A rule whose
// inputs change without an edit (terrain data arriving) emits changed() to be run again.
class RouteRule : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;
    virtual void check(const Route &route, ScanPlanCache *cache, std::vector<ValidationIssue> &issues) = 0;

signals:
    void changed();
};

} // namespace sortie::mission
