#pragma once
// What both geographical-zone fuzzers (fuzz_ed269_zones, fuzz_ed318_zones) hold of a file their
// reader accepted: every zone has an identifier, at least one volume with a usable shape (valid
// positions, rings of 3 or more, a positive radius), limits in order where they share a reference,
// and schedules of at least one day; the zones made of it (core/airspace) keep those.
#include "GeoZoneReader.h"
#include "ZoneFiles.h"

#include <cmath>
#include <cstdlib>

namespace sortie_fuzz {
using namespace sortie::airspace::ed;

inline void checkZone(const GeoZone &z)
{
    if (z.identifier.trimmed().isEmpty() || z.volumes.empty())
        std::abort();
    for (const Volume &v : z.volumes) {
        if (v.circle.has_value() == !v.polygons.empty())
            std::abort();
        if (v.circle && (!v.circle->center.isValid() || !(v.circle->radius > 0)))
            std::abort();
        for (const Polygon &p : v.polygons)
            for (const auto &ring : p.rings) {
                if (ring.size() < 3)
                    std::abort();
                for (const auto &g : ring)
                    if (!g.isValid())
                        std::abort();
            }
        for (const auto &l : {v.lower, v.upper})
            if (l && !std::isfinite(l->metres))
                std::abort();
        if (v.lower && v.upper && v.lower->reference == v.upper->reference && !(v.upper->metres > v.lower->metres))
            std::abort();
    }
    for (const TimePeriod &p : z.applicability) {
        if (p.start && p.end && !(*p.end > *p.start))
            std::abort();
        for (const DailyPeriod &d : p.schedule)
            if (d.days == 0 || d.days > 0x7f)
                std::abort();
    }
    // When it applies is answered for any window, without reading the clock.
    const QDateTime t = QDateTime::fromSecsSinceEpoch(1780000000, QTimeZone::utc());
    (void)z.appliesDuring({t, t.addSecs(3600)});
}

// Aborts (a finding) on any file the reader accepted that breaks what the header says.
template<typename Read>
void checkGeoZoneRead(const Read &read)
{
    if (!read.ok())
        return;
    for (const GeoZone &z : read->zones)
        checkZone(z);
    const sortie::airspace::ZoneFile zones = sortie::airspace::zonesOfGeoZones(read.value());
    for (const auto &z : zones.zones)
        if (!z.geoZone || z.volume < 1 || size_t(z.volume) > z.geoZone->volumes.size())
            std::abort();
}
} // namespace sortie_fuzz
