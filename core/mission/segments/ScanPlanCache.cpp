#include "ScanPlanCache.h"

#include <algorithm>

namespace sortie::mission {

const AreaScanOutcome &ScanPlanCache::outcome(const AreaScan &scan)
{
    for (Entry &e : m_entries) {
        if (e.scan.polygon == scan.polygon && e.scan.parameters == scan.parameters) {
            e.used = true;
            return e.outcome;
        }
    }
    if (m_entries.size() >= kMaxEntries)
        m_entries.erase(m_entries.begin());  // the oldest; a cache used without retainRecentlyUsed stays bounded
    m_entries.push_back({scan, planAreaScan(scan), true});
    return m_entries.back().outcome;
}

void ScanPlanCache::retainRecentlyUsed()
{
    m_entries.erase(std::remove_if(m_entries.begin(), m_entries.end(), [](const Entry &e) { return !e.used; }),
                    m_entries.end());
    for (Entry &e : m_entries)
        e.used = false;
}

const AreaScanOutcome &scanOutcome(const AreaScan &scan, ScanPlanCache *cache, AreaScanOutcome &scratch)
{
    if (cache)
        return cache->outcome(scan);
    scratch = planAreaScan(scan);
    return scratch;
}

} // namespace sortie::mission
