#pragma once

#include "GeoPoint.h"
#include "GeoZone.h"
#include "RouteFence.h"
#include "TerrainProfile.h"

#include <QString>

#include <memory>
#include <optional>
#include <variant>
#include <vector>

namespace sortie::airspace {

using mission::GeoPoint;
using terrain::HeightReference;

// Exclusion: keep out. Inclusion: stay inside (several inclusion zones are one permitted area,
// their union, as PX4 and QGroundControl fences are).
enum class ZoneKind { Exclusion, Inclusion };
// Where a zone came from; what the operator is told in a tooltip, a message, the CLI.
enum class ZoneSource { File, ServerAerodrome, ServerCustom, VehicleFence };

// A floor or a ceiling: metres above the reference (AMSL, the ground under the point, home's ground).
struct HeightLimit
{
    double metres = 0.0;
    HeightReference reference = HeightReference::Amsl;
    bool operator==(const HeightLimit &) const = default;
};

// One polygon: rings[0] the outer boundary, the others holes; open rings (no closing vertex).
struct ZonePolygon
{
    std::vector<std::vector<GeoPoint>> rings;
    bool operator==(const ZonePolygon &) const = default;
};

// One or more polygons (a GeoJSON MultiPolygon, a KML MultiGeometry) as one zone.
struct ZonePolygons
{
    std::vector<ZonePolygon> parts;
    bool operator==(const ZonePolygons &) const = default;
};

struct ZoneCircle
{
    GeoPoint center;
    double radius = 0.0;  // metres
    bool operator==(const ZoneCircle &) const = default;
};

// A cone frustum (the HCI schema's ConeFrustum, an aerodrome's funnel): a circle whose radius goes
// linearly from bottomRadius at the zone's floor to topRadius at its ceiling (both needed, in the
// same reference).
struct ZoneConeFrustum
{
    GeoPoint center;
    double bottomRadius = 0.0;
    double topRadius = 0.0;
    bool operator==(const ZoneConeFrustum &) const = default;
};

using ZoneShape = std::variant<ZonePolygons, ZoneCircle, ZoneConeFrustum>;

struct Zone
{
    QString name;
    ZoneKind kind = ZoneKind::Exclusion;
    ZoneShape shape;
    std::optional<HeightLimit> floor;    // none: from the ground
    std::optional<HeightLimit> ceiling;  // none: unlimited
    ZoneSource source = ZoneSource::File;
    QString origin;  // the file (and feature) or server object it came from
    bool active = true;
    // A server zone's object (NoFlightZone id and version): what an edit or a delete addresses.
    // None for zones from files and fences, and for a custom zone not saved yet.
    std::optional<int> serverId;
    int serverVersion = 0;
    // A volume of a UAS geographical zone (ED-269 / ED-318): that zone (its restriction, when it
    // applies, its authorities and message) and the volume's place in its geometry, from 1. None
    // and 0 for every other zone.
    std::shared_ptr<const ed::GeoZone> geoZone;
    int volume = 0;
    bool operator==(const Zone &) const = default;
};

// "AMSL", "AGL", "above home"
QString referenceName(HeightReference reference);
// "exclusion" / "inclusion", "file", "server aerodrome", ...
QString kindName(ZoneKind kind);
QString sourceName(ZoneSource source);
// "150 m AMSL", "ground", "unlimited"
QString limitText(const std::optional<HeightLimit> &limit, bool ceiling);

// Why a zone's polygons cannot be checked (a ring crossing itself, a hole outside its polygon, a
// spike), as Boost.Geometry's validity check says it; empty when they can (or it has none). The
// readers leave such a zone out naming it.
QString shapeProblem(const Zone &zone);

// A .plan's geofence as zones: "<prefix> polygon 1", "<prefix> circle 2"; the whole column (a
// .plan fence has no altitude limits). Rally points and the breach return are not zones.
std::vector<Zone> zonesOfFence(const mission::RouteFence &fence, const QString &prefix, ZoneSource source, const QString &origin);

} // namespace sortie::airspace
