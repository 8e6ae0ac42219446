#include "Segment.h"

#include "AlgorithmCatalog.h"
#include "Camera.h"
#include "LocalTangentPlane.h"

#include <cmath>

namespace sortie::mission {

namespace {
constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

std::optional<double> numberValue(const AlgorithmSegment &a, QStringView name)
{
    const QString *v = a.value(name);
    return v ? parseParameterNumber(*v) : std::nullopt;
}
} // namespace

GeoPoint anchorOf(const Segment &s)
{
    if (const Waypoint *w = asWaypoint(s))
        return w->position;
    if (const AreaScan *scan = asAreaScan(s))
        return scan->polygon.empty() ? GeoPoint{} : scan->polygon.front();
    const AlgorithmSegment &a = std::get<AlgorithmSegment>(s);
    return a.points.empty() ? GeoPoint{} : a.points.front().position;
}

void moveSegmentTo(Segment &s, const GeoPoint &anchor)
{
    if (Waypoint *w = asWaypoint(s)) {
        w->position = anchor;
        return;
    }
    const LocalTangentPlane from(anchorOf(s)), to(anchor);
    const auto move = [&](GeoPoint &p) { p = to.unproject(from.project(p)); };
    if (AreaScan *scan = asAreaScan(s)) {
        for (GeoPoint &p : scan->polygon)
            move(p);
        return;
    }
    for (FigurePoint &p : std::get<AlgorithmSegment>(s).points)
        move(p.position);
}

double altitudeOf(const Segment &s)
{
    if (const Waypoint *w = asWaypoint(s))
        return w->altitude;
    if (const AreaScan *scan = asAreaScan(s))
        return scanAltitude(scan->parameters);
    const AlgorithmSegment &a = std::get<AlgorithmSegment>(s);
    if (const auto h = numberValue(a, u"height"))
        return *h;
    if (a.figure == FigureType::Point || a.figure == FigureType::Circle)  // the point carries it
        return a.points.empty() ? kMissing : a.points.front().altitude;
    return kMissing;
}

AltitudeType altitudeTypeOf(const Segment &s)
{
    if (const Waypoint *w = asWaypoint(s))
        return w->altitudeType;
    if (const AreaScan *scan = asAreaScan(s))
        return scan->parameters.altitudeType;
    const AlgorithmSegment &a = std::get<AlgorithmSegment>(s);
    if (const QString *t = a.value(u"altitudeType"))
        return t->compare(QLatin1String("AGL"), Qt::CaseInsensitive) == 0 ? AltitudeType::Agl : AltitudeType::Amsl;
    if (const QString *agl = a.value(u"heightAgl"))
        return parseParameterBoolean(*agl).value_or(true) ? AltitudeType::Agl : AltitudeType::Amsl;
    return a.points.empty() ? AltitudeType::Agl : a.points.front().altitudeType;
}

double speedOf(const Segment &s)
{
    if (const Waypoint *w = asWaypoint(s))
        return w->speed;
    if (const AreaScan *scan = asAreaScan(s))
        return scan->parameters.speed;
    return numberValue(std::get<AlgorithmSegment>(s), u"speed").value_or(kMissing);
}

const ServerOrigin &originOf(const Segment &s)
{
    return std::visit([](const auto &v) -> const ServerOrigin & { return v.origin; }, s);
}

QString segmentLabel(int row, const Segment &s)
{
    if (isWaypoint(s))
        return QStringLiteral("Waypoint %1").arg(row + 1);
    if (isAreaScan(s))
        return QStringLiteral("Area scan %1").arg(row + 1);
    return QStringLiteral("%1 %2").arg(algorithmLabel(std::get<AlgorithmSegment>(s))).arg(row + 1);
}

QString segmentKindName(const Segment &s)
{
    if (const Waypoint *w = asWaypoint(s))
        return roleName(w->role);
    if (isAreaScan(s))
        return QStringLiteral("areaScan");
    switch (std::get<AlgorithmSegment>(s).kind()) {
    case AlgorithmKind::Circle: return QStringLiteral("circle");
    case AlgorithmKind::Perimeter: return QStringLiteral("perimeter");
    case AlgorithmKind::Photogrammetry: return QStringLiteral("photogrammetry");
    case AlgorithmKind::Corridor: return QStringLiteral("corridor");
    case AlgorithmKind::ExpandingSquare: return QStringLiteral("expandingSquare");
    case AlgorithmKind::CreepingLine: return QStringLiteral("creepingLine");
    case AlgorithmKind::FacadeScanner: return QStringLiteral("facadeScanner");
    case AlgorithmKind::AreaScan: return QStringLiteral("areaScan");
    case AlgorithmKind::Waypoint: return QStringLiteral("waypoint");
    case AlgorithmKind::TakeOff: return QStringLiteral("takeoff");
    case AlgorithmKind::Landing: return QStringLiteral("land");
    case AlgorithmKind::Unknown: break;
    }
    return QStringLiteral("unknown");
}

std::vector<GeoPoint> figureOf(const Segment &s)
{
    if (const AreaScan *scan = asAreaScan(s))
        return scan->polygon;
    std::vector<GeoPoint> out;
    if (const AlgorithmSegment *a = asAlgorithmSegment(s))
        for (const FigurePoint &p : a->points)
            out.push_back(p.position);
    return out;
}

std::optional<AreaScan> scanOf(const Segment &s, const std::vector<ProfileCamera> &cameras)
{
    if (const AreaScan *scan = asAreaScan(s))
        return *scan;
    const AlgorithmSegment *a = asAlgorithmSegment(s);
    if (!a || a->kind() != AlgorithmKind::Photogrammetry)
        return std::nullopt;
    const AlgorithmDefinition *def = AlgorithmCatalog::builtIn().byKind(AlgorithmKind::Photogrammetry);
    const ParameterReader read(*def, a->parameters);
    AreaScan scan;
    scan.polygon = figureOf(s);
    AreaScanParameters &p = scan.parameters;
    if (const auto camera = resolveCamera(read.selection(u"camera"), cameras))
        p.camera = *camera;
    if (!read.boolean(u"camTopFacingForward", true)) {  // the image's width runs along the track
        std::swap(p.camera.sensorWidthMm, p.camera.sensorHeightMm);
        std::swap(p.camera.imageWidthPx, p.camera.imageHeightPx);
    }
    p.heightMode = ScanHeightMode::GroundSampleDistance;
    p.groundSampleDistanceCm = read.number(u"groundSampleDistance", p.groundSampleDistanceCm);
    p.frontOverlapPercent = read.number(u"overlapForward", p.frontOverlapPercent);
    p.sideOverlapPercent = read.number(u"overlapSide", p.sideOverlapPercent);
    p.directionDeg = read.number(u"directionAngle", p.directionDeg);
    p.turnaroundMeters = read.number(u"overshoot", 0.0);
    p.speed = read.number(u"speed", p.speed);
    p.altitudeType = altitudeTypeOf(s);
    syncDerivedFields(p);
    return scan;
}

} // namespace sortie::mission
