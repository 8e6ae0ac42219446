#pragma once

#include "AreaScanPlanner.h"

#include <vector>

namespace sortie::mission {

// Remembers the plans of the area scans last seen, so that statistics and validation plan each
// unchanged scan once. Not thread-safe; one per analyzer.
class ScanPlanCache
{
public:
    const AreaScanOutcome &outcome(const AreaScan &scan);
    // Forget the scans not asked for since the previous call.
    void retainRecentlyUsed();
    size_t size() const { return m_entries.size(); }
    static constexpr size_t kMaxEntries = 64;

private:
    struct Entry { AreaScan scan; AreaScanOutcome outcome; bool used; };
    std::vector<Entry> m_entries;
};

// The outcome from the cache when there is one, else planned now into scratch.
const AreaScanOutcome &scanOutcome(const AreaScan &scan, ScanPlanCache *cache, AreaScanOutcome &scratch);

} // namespace sortie::mission
