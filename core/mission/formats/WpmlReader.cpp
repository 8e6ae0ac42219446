// Reading a WPML KMZ: its waylines into routes, their heights into AMSL or AGL, the take-off point
// into the route's home, and a notice for every element not kept.
#include "WpmlFormat.h"

#include "DjiDroneModels.h"
#include "Egm96Geoid.h"
#include "NumberText.h"
#include "WpmlDocumentReader.h"
#include "WpmlGeoidAccess.h"
#include "WpmlReadActions.h"
#include "WpmlSchema.h"
#include "ZipArchive.h"

#include <algorithm>

namespace sortie::mission::formats {
namespace {

using namespace wpml;

TurnType turnTypeOf(const ReadPoint &p, const QString &where, QStringList *notices)
{
    const auto mode = parseName<TurnMode>(p.turnMode, turnModeName,
                                          {TurnMode::Coordinated, TurnMode::StopStraight, TurnMode::StopCurved, TurnMode::PassCurved});
    if (!mode) {
        if (!p.turnMode.isEmpty())
            *notices << QStringLiteral("%1: unknown turn mode \"%2\" read as stop-and-turn").arg(where, p.turnMode);
        return TurnType::StopAndTurn;
    }
    switch (*mode) {
    case TurnMode::Coordinated: return TurnType::BankTurn;
    case TurnMode::StopStraight: return TurnType::StopAndTurn;
    case TurnMode::StopCurved:
        *notices << QStringLiteral("%1: \"stop with a curved path\" read as stop-and-turn").arg(where);
        return TurnType::StopAndTurn;
    case TurnMode::PassCurved: return p.straight ? TurnType::Straight : TurnType::Spline;
    }
    return TurnType::StopAndTurn;
}

// A wayline's heights in Sortie's terms: the executeHeightMode's reference turned into AMSL where
// the file says enough (the take-off point, the geoid), else AGL.
class WaylineHeights
{
public:
    WaylineHeights(QString mode, std::optional<HomePosition> home, GeoidAccess *geoid)
        : m_mode(std::move(mode)), m_home(std::move(home)), m_geoid(geoid) {}

    Result<std::pair<double, AltitudeType>> convert(const GeoPoint &p, double height, const QString &where)
    {
        if (m_mode == QLatin1String("WGS84")) {
            const Result<const datum::Egm96Geoid *> geoid = m_geoid->get(where + QStringLiteral("'s WGS-84 ellipsoidal height"));
            if (!geoid)
                return geoid.error();
            const auto amsl = (*geoid)->amslFromEllipsoidal(p.latitude, p.longitude, height);
            if (!amsl)
                return MissionError{QStringLiteral("%1: no EGM96 geoid height there").arg(where), {}, 0, 0, {}};
            return std::pair{*amsl, AltitudeType::Amsl};
        }
        if (m_mode == QLatin1String("realTimeFollowSurface"))
            return std::pair{height, AltitudeType::Agl};
        if (m_home)
            return std::pair{m_home->altitudeAmsl + height, AltitudeType::Amsl};  // above take-off: exact with its AMSL altitude
        return std::pair{height, AltitudeType::Agl};
    }

private:
    QString m_mode;
    std::optional<HomePosition> m_home;
    GeoidAccess *m_geoid;
};

struct Wayline
{
    int number = 1;  // 1-based, for notices
    bool last = true;
    std::optional<HomePosition> home;
};

Result<Route> routeOf(const ReadFolder &wayline, const ReadFolder *templateFolder, const ReadDocument &doc, const Wayline &which,
                      GeoidAccess *geoid, const QString &file, QStringList *notices)
{
    const QString prefix = QStringLiteral("wayline %1").arg(which.number);
    if (wayline.points.empty())
        return MissionError{QStringLiteral("%1 has no waypoints").arg(prefix), file, 0, 0, {}};
    const bool fromTemplate = templateFolder && templateFolder->heightMode == QLatin1String("EGM96")
                              && templateFolder->points.size() == wayline.points.size();
    static const QStringList known = {QStringLiteral("WGS84"), QStringLiteral("relativeToStartPoint"), QStringLiteral("realTimeFollowSurface")};
    if (!wayline.heightMode.isEmpty() && !known.contains(wayline.heightMode))
        return MissionError{QStringLiteral("%1: unknown executeHeightMode \"%2\"").arg(prefix, wayline.heightMode), file, 0, 0, {}};
    const bool relative = wayline.heightMode.isEmpty() || wayline.heightMode == QLatin1String("relativeToStartPoint");
    if (relative && !fromTemplate && !which.home)
        *notices << QStringLiteral("%1: heights relative to take-off read as AGL: equal only over level ground (the file holds no take-off point)").arg(prefix);
    WaylineHeights heights(wayline.heightMode, which.home, geoid);

    Route route;
    const size_t n = wayline.points.size();
    std::vector<const ReadPoint *> byIndex(n, nullptr);
    for (const ReadPoint &p : wayline.points) {
        const int i = p.index.value_or(int(&p - wayline.points.data()));
        if (i < 0 || size_t(i) >= n || byIndex[size_t(i)])
            return MissionError{QStringLiteral("%1: waypoint index %2 is out of order or repeated").arg(prefix).arg(i), file, p.line, 0, {}};
        byIndex[size_t(i)] = &p;
    }
    std::optional<QString> poi;
    std::map<QString, std::vector<int>> headings;  // heading modes not kept, by waypoint
    for (size_t i = 0; i < n; ++i) {
        const ReadPoint &p = *byIndex[i];
        const QString where = QStringLiteral("%1, waypoint %2").arg(prefix).arg(i + 1);
        if (!p.position)
            return MissionError{QStringLiteral("%1 has no coordinates").arg(where), file, p.line, 0, {}};
        const ReadPoint &heightSource = fromTemplate ? templateFolder->points[i] : p;
        if (!heightSource.height)
            return MissionError{QStringLiteral("%1 has no height").arg(where), file, heightSource.line, 0, {}};
        Waypoint w;
        w.position = *p.position;
        if (fromTemplate) {
            w.altitude = *heightSource.height;
            w.altitudeType = AltitudeType::Amsl;
        } else {
            const auto h = heights.convert(w.position, *heightSource.height, where);
            if (!h)
                return h.error().withFile(file);
            std::tie(w.altitude, w.altitudeType) = *h;
        }
        // DJI's waypointSpeed leaves the point; Sortie's speed arrives at it.
        const auto arriving = i == 0 ? doc.transitionalSpeed : byIndex[i - 1]->speed;
        if (!arriving || !(*arriving > 0.0))
            return MissionError{QStringLiteral("%1 has no speed to arrive with").arg(where), file, p.line, 0, {}};
        w.speed = *arriving;
        w.turnType = turnTypeOf(p, where, notices);
        if (p.headingMode == QLatin1String("towardPOI") && p.poi != poi) {
            const QStringList parts = p.poi.split(QLatin1Char(','));
            const auto lat = parts.size() == 3 ? parseNumber(parts[0].trimmed().toLatin1()) : std::nullopt;
            const auto lon = parts.size() == 3 ? parseNumber(parts[1].trimmed().toLatin1()) : std::nullopt;
            const auto h = parts.size() == 3 ? parseNumber(parts[2].trimmed().toLatin1()) : std::nullopt;
            const GeoPoint at{lat.value_or(1000.0), lon.value_or(1000.0)};
            if (!h || !at.isValid())
                return MissionError{QStringLiteral("%1: point of interest \"%2\" is not latitude,longitude,height").arg(where, p.poi), file, p.line, 0, {}};
            const auto target = heights.convert(at, *h, where + QStringLiteral("'s point of interest"));
            if (!target)
                return target.error().withFile(file);
            w.actions.push_back(PoiAction{at, target->first, target->second});
            poi = p.poi;
        } else if (p.headingMode != QLatin1String("towardPOI")) {
            poi.reset();
            if (!p.headingMode.isEmpty() && p.headingMode != QLatin1String("followWayline"))
                headings[p.headingMode].push_back(int(i + 1));
        }
        route.segments.push_back(std::move(w));
    }
    for (const auto &[mode, points] : headings)
        *notices << QStringLiteral("%1, %2: the heading mode \"%3\" is not kept; the aircraft faces along the route")
                        .arg(prefix, waypointList(points), mode);

    const Result<void> actions = readActions(wayline, byIndex, route, prefix, file, notices);
    if (!actions)
        return actions.error();

    // One finish action for the file: it ends the last wayline.
    if (which.last) {
        if (doc.finishAction == QLatin1String("goHome")) {
            route.settings.endAction = EndAction::ReturnHome;
        } else if (doc.finishAction == QLatin1String("autoLand")) {
            asWaypoint(route.segments.back())->role = WaypointRole::Land;
        } else if (doc.finishAction == QLatin1String("gotoFirstWaypoint")) {
            *notices << QStringLiteral("%1: the route ends by flying back to its first waypoint; Sortie's route ends at its last waypoint").arg(prefix);
        }
    }
    route.settings.home = which.home;
    for (const auto &[element, points] : wayline.unknown) {
        std::vector<int> waypoints;  // (a loop, not a lambda: clang 14 cannot capture a structured binding)
        for (int p : points)
            if (p > 0)
                waypoints.push_back(p);
        *notices << (waypoints.empty() ? QStringLiteral("%1: %2 is not kept").arg(prefix, element)
                                       : QStringLiteral("%1, %2: %3 is not kept").arg(prefix, waypointList(waypoints), element));
    }
    return route;
}

// wpml:takeOffRefPoint: "latitude,longitude,height", the height ellipsoidal (WPML's template
// reference), kept as the route's home with its AMSL altitude.
Result<std::optional<HomePosition>> takeoffOf(const ReadDocument &doc, GeoidAccess *geoid, const QString &file)
{
    if (doc.takeOffRefPoint.isEmpty())
        return std::optional<HomePosition>();
    const QStringList parts = doc.takeOffRefPoint.split(QLatin1Char(','));
    const auto lat = parts.size() == 3 ? parseNumber(parts[0].trimmed().toLatin1()) : std::nullopt;
    const auto lon = parts.size() == 3 ? parseNumber(parts[1].trimmed().toLatin1()) : std::nullopt;
    const auto h = parts.size() == 3 ? parseNumber(parts[2].trimmed().toLatin1()) : std::nullopt;
    const GeoPoint at{lat.value_or(1000.0), lon.value_or(1000.0)};
    if (!h || !at.isValid())
        return MissionError{QStringLiteral("takeOffRefPoint \"%1\" is not latitude,longitude,height").arg(doc.takeOffRefPoint), file, 0, 0, {}};
    const Result<const datum::Egm96Geoid *> g = geoid->get(QStringLiteral("the take-off point's ellipsoidal height"));
    if (!g)
        return g.error().withFile(file);
    const auto amsl = (*g)->amslFromEllipsoidal(at.latitude, at.longitude, *h);
    if (!amsl)
        return MissionError{QStringLiteral("takeOffRefPoint: no EGM96 geoid height there"), file, 0, 0, {}};
    return std::optional<HomePosition>(HomePosition{at, *amsl});
}

// The aircraft and payload the file declares, named when Sortie does not know them or keeps them not.
const DjiDroneModel *aircraftOf(const ReadDocument &doc, QStringList *notices)
{
    if (!doc.droneEnum)
        return nullptr;
    const DjiDroneModel *model = findDjiDroneModel(*doc.droneEnum, doc.droneSubEnum.value_or(0));
    if (!model) {
        *notices << QStringLiteral("droneEnumValue %1/%2 is not an aircraft Sortie knows: the routes name no DJI aircraft (--drone chooses one on export)")
                        .arg(*doc.droneEnum).arg(doc.droneSubEnum.value_or(0));
        return nullptr;
    }
    if (doc.payloadEnum && (model->payloads.empty() || model->payloads.front().enumValue != *doc.payloadEnum)) {
        const auto it = std::find_if(model->payloads.begin(), model->payloads.end(), [&](const DjiPayload &p) { return p.enumValue == *doc.payloadEnum; });
        *notices << (it == model->payloads.end()
                         ? QStringLiteral("payloadEnumValue %1 is not a payload Sortie knows on the %2 and is not kept").arg(*doc.payloadEnum).arg(model->name)
                         : QStringLiteral("the payload %1 is not kept with the routes: an export writes the %2 unless --payload %3 is given")
                               .arg(it->name, model->payloads.front().name, it->key));
    }
    return model;
}

// A WPML file states no altitude limit of its own: its routes keep the aircraft's (the highest
// altitude limit DJI Pilot 2 can set on it, above the take-off point), or, for an aircraft Sortie
// does not know, the highest any of them can set. Sortie's own default of 120 m above the take-off
// point would refuse real survey files over rising ground; the legal 120 m above the surface is
// judged by the terrain rules, where the ground is known.
double altitudeLimitOf(const DjiDroneModel *model)
{
    if (model)
        return model->maxAltitudeLimit;
    double highest = 0.0;
    for (const DjiDroneModel &m : djiDroneModels())
        highest = std::max(highest, m.maxAltitudeLimit);
    return highest;
}

} // namespace

Result<WpmlImport> readWpml(const QByteArray &data, const WpmlReadOptions &options)
{
    QByteArray waylines, templateKml;
    QString waylinesName = QStringLiteral("waylines.wpml");
    if (data.startsWith("PK")) {
        // Only the two documents are inflated, within the archive limits (ZipArchive.h).
        Result<ZipReader> opened = ZipReader::open(data);
        if (!opened)
            return opened.error();
        ZipReader archive = std::move(opened).value();
        QString waylinesPath, templatePath;
        for (const QString &path : archive.paths()) {
            if (waylinesPath.isEmpty() && path.endsWith(QLatin1String("waylines.wpml"), Qt::CaseInsensitive))
                waylinesPath = path;
            else if (templatePath.isEmpty() && path.endsWith(QLatin1String("template.kml"), Qt::CaseInsensitive))
                templatePath = path;
        }
        if (waylinesPath.isEmpty())
            return MissionError{QStringLiteral("the KMZ holds no wpmz/waylines.wpml: not a DJI WPML route"), {}, 0, 0, {}};
        waylinesName = waylinesPath;
        Result<QByteArray> read = archive.read(waylinesName);
        if (!read)
            return read.error();
        waylines = std::move(read).value();
        if (!templatePath.isEmpty()) {
            Result<QByteArray> t = archive.read(templatePath);
            if (!t)
                return t.error();
            templateKml = std::move(t).value();
        }
        if (waylines.isEmpty())
            return MissionError{QStringLiteral("the KMZ's %1 is empty").arg(waylinesName), {}, 0, 0, {}};
    } else {
        waylines = data;
    }
    const QString templateName = QStringLiteral("wpmz/template.kml");
    const Result<ReadDocument> doc = readDocument(waylines, waylinesName);
    if (!doc)
        return doc.error();
    std::optional<ReadDocument> templ;
    if (!templateKml.isEmpty()) {
        Result<ReadDocument> t = readDocument(templateKml, templateName);
        if (!t)
            return t.error();
        templ = std::move(t).value();
    }
    if (doc->folders.empty())
        return MissionError{QStringLiteral("no wayline (Folder) in the document"), waylinesName, 0, 0, {}};

    WpmlImport out;
    GeoidAccess geoid(options.geoid);
    // The take-off point: DJI's editors write it in the template, but take it from either.
    const ReadDocument &takeoffDoc = doc->takeOffRefPoint.isEmpty() && templ ? *templ : *doc;
    const Result<std::optional<HomePosition>> home = takeoffOf(takeoffDoc, &geoid, &takeoffDoc == &*doc ? waylinesName : templateName);
    if (!home)
        return home.error();
    if (takeoffDoc.takeOffRefPointAglHeight && *takeoffDoc.takeOffRefPointAglHeight != 0.0)
        out.notices << QStringLiteral("the take-off point's height above the ground (takeOffRefPointAGLHeight %1 m) is not kept")
                           .arg(*takeoffDoc.takeOffRefPointAglHeight);
    const DjiDroneModel *aircraft = aircraftOf(*doc, &out.notices);
    out.droneName = aircraft ? aircraft->name : QString();
    if (!doc->unknown.isEmpty())
        out.notices << QStringLiteral("mission config: not kept: %1").arg(doc->unknown.join(QStringLiteral(", ")));
    if (templ) {
        // The template is DJI's editing state; Sortie reads its EGM96 heights and take-off point.
        QStringList editing = templ->unknown;
        for (const ReadFolder &f : templ->folders) {
            if (!f.templateType.isEmpty() && f.templateType != QLatin1String("waypoint"))
                editing << QStringLiteral("the %1 template's area and settings").arg(f.templateType);
            for (const auto &entry : f.unknown)
                editing << entry.first;
        }
        editing.removeDuplicates();
        if (!editing.isEmpty())
            out.notices << QStringLiteral("template.kml: not kept (the waylines are): %1").arg(editing.join(QStringLiteral(", ")));
    }
    const size_t count = doc->folders.size();
    for (size_t f = 0; f < count; ++f) {
        const ReadFolder *tf = templ && templ->folders.size() == count ? &templ->folders[f] : nullptr;
        const Wayline which{int(f + 1), f + 1 == count, *home};
        Result<Route> r = routeOf(doc->folders[f], tf, *doc, which, &geoid, waylinesName, &out.notices);
        if (!r)
            return r.error();
        Route route = std::move(r).value();
        route.settings.profile.name = out.droneName;
        route.settings.maxAltitude = altitudeLimitOf(aircraft);
        if (count > 1)
            route.settings.name = QStringLiteral("Wayline %1").arg(f + 1);
        out.routes.push_back(std::move(route));
    }
    out.notices.removeDuplicates();
    return out;
}

} // namespace sortie::mission::formats
