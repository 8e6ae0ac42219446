#include "WpmlFormat.h"

#include "DjiDroneModels.h"
#include "NumberText.h"
#include "WpmlSchema.h"
#include "ZipArchive.h"

#include <QXmlStreamReader>

#include <map>

namespace sortie::mission::formats {
namespace {

using namespace wpml;

MissionError errorAt(const QString &file, const QXmlStreamReader &x, const QString &message)
{
    return MissionError{message, file, int(x.lineNumber()), int(x.columnNumber()), {}};
}

struct ReadAction
{
    QString func;
    std::map<QString, QString> params;
};

struct ReadGroup
{
    int start = 0;
    int end = 0;
    QString trigger;
    std::optional<double> interval;
    std::vector<ReadAction> actions;
};

struct ReadPoint
{
    std::optional<GeoPoint> position;
    std::optional<int> index;
    std::optional<double> height;  // executeHeight (waylines) or height (template)
    std::optional<double> speed;
    QString turnMode;
    QString headingMode;
    QString poi;
    bool straight = true;
    std::vector<ReadGroup> groups;
    int line = 0;
};

struct ReadFolder
{
    QString heightMode;  // executeHeightMode or the template's heightMode
    std::vector<ReadPoint> points;
};

struct ReadDocument
{
    QString finishAction;
    std::optional<double> transitionalSpeed;
    std::optional<int> droneEnum, droneSubEnum;
    std::vector<ReadFolder> folders;
};

// Reads the parts of a WPML document Sortie uses, by local name within the WPML and KML namespaces
// (any wpmz version). Unknown elements are skipped.
class DocumentReader
{
public:
    DocumentReader(const QByteArray &data, QString file) : x(data), m_file(std::move(file)) {}

    Result<ReadDocument> read()
    {
        ReadDocument doc;
        while (x.readNextStartElement()) {
            if (name() == QLatin1String("kml") || name() == QLatin1String("Document"))
                continue;  // descend
            if (name() == QLatin1String("missionConfig")) {
                readMissionConfig(doc);
            } else if (name() == QLatin1String("Folder")) {
                Result<ReadFolder> f = readFolder();
                if (!f)
                    return f.error();
                doc.folders.push_back(std::move(f).value());
            } else {
                x.skipCurrentElement();
            }
            if (m_error)
                return *m_error;
        }
        if (x.hasError())
            return errorAt(m_file, x, QStringLiteral("malformed XML: %1").arg(x.errorString()));
        return doc;
    }

private:
    QStringView name() const { return x.name(); }
    QString text() { return x.readElementText(QXmlStreamReader::SkipChildElements).trimmed(); }

    std::optional<double> number(const QString &what)
    {
        const QString t = text();
        const auto v = parseNumber(t.toLatin1());
        if (!v && !m_error)
            m_error = errorAt(m_file, x, QStringLiteral("%1 is not a number: \"%2\"").arg(what, t));
        return v;
    }

    void readMissionConfig(ReadDocument &doc)
    {
        while (x.readNextStartElement()) {
            if (name() == QLatin1String("finishAction")) {
                doc.finishAction = text();
            } else if (name() == QLatin1String("globalTransitionalSpeed")) {
                doc.transitionalSpeed = number(QStringLiteral("globalTransitionalSpeed"));
            } else if (name() == QLatin1String("droneInfo")) {
                while (x.readNextStartElement()) {
                    if (name() == QLatin1String("droneEnumValue"))
                        doc.droneEnum = text().toInt();
                    else if (name() == QLatin1String("droneSubEnumValue"))
                        doc.droneSubEnum = text().toInt();
                    else
                        x.skipCurrentElement();
                }
            } else {
                x.skipCurrentElement();
            }
        }
    }

    Result<ReadFolder> readFolder()
    {
        ReadFolder f;
        while (x.readNextStartElement()) {
            if (name() == QLatin1String("executeHeightMode")) {
                f.heightMode = text();
            } else if (name() == QLatin1String("waylineCoordinateSysParam")) {
                while (x.readNextStartElement()) {
                    if (name() == QLatin1String("heightMode"))
                        f.heightMode = text();
                    else
                        x.skipCurrentElement();
                }
            } else if (name() == QLatin1String("Placemark")) {
                ReadPoint p = readPlacemark();
                if (m_error)
                    return *m_error;
                f.points.push_back(std::move(p));
            } else {
                x.skipCurrentElement();
            }
            if (m_error)
                return *m_error;
        }
        return f;
    }

    ReadPoint readPlacemark()
    {
        ReadPoint p;
        p.line = int(x.lineNumber());
        while (x.readNextStartElement()) {
            const QStringView n = name();
            if (n == QLatin1String("Point")) {
                while (x.readNextStartElement()) {
                    if (name() != QLatin1String("coordinates")) {
                        x.skipCurrentElement();
                        continue;
                    }
                    const QString t = text();
                    const QStringList parts = t.split(QLatin1Char(','));
                    const auto lon = parts.size() >= 2 ? parseNumber(parts[0].trimmed().toLatin1()) : std::nullopt;
                    const auto lat = parts.size() >= 2 ? parseNumber(parts[1].trimmed().toLatin1()) : std::nullopt;
                    const GeoPoint g{lat.value_or(1000.0), lon.value_or(1000.0)};
                    if (!lat || !lon || !g.isValid()) {
                        m_error = errorAt(m_file, x, QStringLiteral("coordinates \"%1\" are not longitude,latitude in degrees").arg(t));
                        return p;
                    }
                    p.position = g;
                }
            } else if (n == QLatin1String("index")) {
                bool ok = false;
                p.index = text().toInt(&ok);
                if (!ok) {
                    m_error = errorAt(m_file, x, QStringLiteral("a waypoint index is not a whole number"));
                    return p;
                }
            } else if (n == QLatin1String("executeHeight") || n == QLatin1String("height")) {
                p.height = number(n.toString());
            } else if (n == QLatin1String("waypointSpeed")) {
                p.speed = number(QStringLiteral("waypointSpeed"));
            } else if (n == QLatin1String("useStraightLine")) {
                p.straight = text() != QLatin1String("0");
            } else if (n == QLatin1String("waypointHeadingParam")) {
                while (x.readNextStartElement()) {
                    if (name() == QLatin1String("waypointHeadingMode"))
                        p.headingMode = text();
                    else if (name() == QLatin1String("waypointPoiPoint"))
                        p.poi = text();
                    else
                        x.skipCurrentElement();
                }
            } else if (n == QLatin1String("waypointTurnParam")) {
                while (x.readNextStartElement()) {
                    if (name() == QLatin1String("waypointTurnMode"))
                        p.turnMode = text();
                    else
                        x.skipCurrentElement();
                }
            } else if (n == QLatin1String("actionGroup")) {
                p.groups.push_back(readGroup());
            } else {
                x.skipCurrentElement();
            }
            if (m_error)
                return p;
        }
        return p;
    }

    ReadGroup readGroup()
    {
        ReadGroup g;
        while (x.readNextStartElement()) {
            const QStringView n = name();
            if (n == QLatin1String("actionGroupStartIndex")) {
                g.start = text().toInt();
            } else if (n == QLatin1String("actionGroupEndIndex")) {
                g.end = text().toInt();
            } else if (n == QLatin1String("actionTrigger")) {
                while (x.readNextStartElement()) {
                    if (name() == QLatin1String("actionTriggerType"))
                        g.trigger = text();
                    else if (name() == QLatin1String("actionTriggerParam"))
                        g.interval = number(QStringLiteral("actionTriggerParam"));
                    else
                        x.skipCurrentElement();
                }
            } else if (n == QLatin1String("action")) {
                ReadAction a;
                while (x.readNextStartElement()) {
                    if (name() == QLatin1String("actionActuatorFunc")) {
                        a.func = text();
                    } else if (name() == QLatin1String("actionActuatorFuncParam")) {
                        while (x.readNextStartElement()) {
                            const QString key = name().toString();
                            a.params[key] = text();
                        }
                    } else {
                        x.skipCurrentElement();
                    }
                }
                g.actions.push_back(std::move(a));
            } else {
                x.skipCurrentElement();
            }
        }
        return g;
    }

    QXmlStreamReader x;
    QString m_file;
    std::optional<MissionError> m_error;
};

std::optional<double> paramNumber(const ReadAction &a, const char *key)
{
    const auto it = a.params.find(QString::fromLatin1(key));
    return it == a.params.end() ? std::nullopt : parseNumber(it->second.toLatin1());
}

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

Result<Route> routeOf(const ReadFolder &wayline, const ReadFolder *templateFolder, const ReadDocument &doc,
                      const QString &file, QStringList *notices)
{
    if (wayline.points.empty())
        return MissionError{QStringLiteral("a wayline has no waypoints"), file, 0, 0, {}};
    // Heights: AMSL from an EGM96 template (same waypoints), else the wayline's own reference.
    AltitudeType type = AltitudeType::Agl;
    bool fromTemplate = false;
    if (templateFolder && templateFolder->heightMode == QLatin1String("EGM96") && templateFolder->points.size() == wayline.points.size()) {
        type = AltitudeType::Amsl;
        fromTemplate = true;
    } else if (wayline.heightMode == QLatin1String("relativeToStartPoint") || wayline.heightMode.isEmpty()) {
        *notices << QStringLiteral("heights relative to take-off read as AGL: equal only over level ground");
    } else if (wayline.heightMode == QLatin1String("WGS84")) {
        type = AltitudeType::Amsl;
        *notices << QStringLiteral("WGS-84 ellipsoid heights read as AMSL: they differ by the geoid undulation (tens of metres); check them before flight");
    } else if (wayline.heightMode != QLatin1String("realTimeFollowSurface")) {
        return MissionError{QStringLiteral("unknown executeHeightMode \"%1\"").arg(wayline.heightMode), file, 0, 0, {}};
    }

    Route route;
    const size_t n = wayline.points.size();
    std::vector<const ReadPoint *> byIndex(n, nullptr);
    for (const ReadPoint &p : wayline.points) {
        const int i = p.index.value_or(int(&p - wayline.points.data()));
        if (i < 0 || size_t(i) >= n || byIndex[size_t(i)])
            return MissionError{QStringLiteral("waypoint index %1 is out of order or repeated").arg(i), file, p.line, 0, {}};
        byIndex[size_t(i)] = &p;
    }
    std::optional<QString> poi;
    for (size_t i = 0; i < n; ++i) {
        const ReadPoint &p = *byIndex[i];
        const QString where = QStringLiteral("waypoint %1").arg(i + 1);
        if (!p.position)
            return MissionError{QStringLiteral("%1 has no coordinates").arg(where), file, p.line, 0, {}};
        const ReadPoint &heightSource = fromTemplate ? templateFolder->points[i] : p;
        if (!heightSource.height)
            return MissionError{QStringLiteral("%1 has no height").arg(where), file, heightSource.line, 0, {}};
        Waypoint w;
        w.position = *p.position;
        w.altitude = *heightSource.height;
        w.altitudeType = type;
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
            if (!lat || !lon || !h)
                return MissionError{QStringLiteral("%1: point of interest \"%2\" is not latitude,longitude,height").arg(where, p.poi), file, p.line, 0, {}};
            w.actions.push_back(PoiAction{GeoPoint{*lat, *lon}, *h, type});
            poi = p.poi;
        } else if (p.headingMode != QLatin1String("towardPOI")) {
            poi.reset();
        }
        route.segments.push_back(std::move(w));
    }

    // Actions: groups fired on reaching a point become that waypoint's actions; repeated triggers
    // become a photo series from their first point, stopped at their last.
    for (size_t i = 0; i < n; ++i) {
        for (const ReadGroup &g : byIndex[i]->groups) {
            const QString where = QStringLiteral("waypoint %1").arg(i + 1);
            auto *w = asWaypoint(route.segments[std::clamp<size_t>(size_t(std::max(g.start, 0)), 0, n - 1)]);
            const bool repeated = g.trigger == QLatin1String("multipleDistance") || g.trigger == QLatin1String("multipleTiming");
            for (const ReadAction &a : g.actions) {
                if (repeated) {
                    if (a.func != QLatin1String("takePhoto") || !g.interval || !(*g.interval > 0.0)) {
                        *notices << QStringLiteral("%1: a repeated \"%2\" is not kept").arg(where, a.func);
                        continue;
                    }
                    if (g.trigger == QLatin1String("multipleDistance"))
                        w->actions.push_back(CameraSeriesByDistanceAction{*g.interval, 0, 0.0});
                    else
                        w->actions.push_back(CameraSeriesByTimeAction{*g.interval, 0, 0.0});
                    const size_t last = std::clamp<size_t>(size_t(std::max(g.end, g.start)), 0, n - 1);
                    // Stop it at its last point, unless the route ends there or a camera action follows.
                    auto *endPoint = asWaypoint(route.segments[last]);
                    const bool cameraAtEnd = [&] {
                        for (const ReadGroup &other : byIndex[last]->groups)
                            if (&other != &g && other.start == int(last))
                                for (const ReadAction &oa : other.actions)
                                    if (oa.func == QLatin1String("takePhoto") || oa.func.endsWith(QLatin1String("Record")))
                                        return true;
                        return false;
                    }();
                    if (last + 1 < n && !cameraAtEnd)
                        endPoint->actions.push_back(CameraSeriesByDistanceAction{0.0, 0, 0.0});
                    continue;
                }
                if (g.trigger != QLatin1String("reachPoint") && !g.trigger.isEmpty()) {
                    *notices << QStringLiteral("%1: \"%2\" triggered %3 is done on reaching the point").arg(where, a.func, g.trigger);
                }
                if (a.func == QLatin1String("takePhoto")) {
                    w->actions.push_back(CameraTriggerAction{TriggerState::SingleShot});
                } else if (a.func == QLatin1String("startRecord")) {
                    w->actions.push_back(CameraTriggerAction{TriggerState::StartRecording});
                } else if (a.func == QLatin1String("stopRecord")) {
                    w->actions.push_back(CameraTriggerAction{TriggerState::StopRecording});
                } else if (a.func == QLatin1String("hover")) {
                    const auto s = paramNumber(a, "hoverTime");
                    if (!s)
                        return MissionError{QStringLiteral("%1: hover without a hoverTime").arg(where), file, byIndex[i]->line, 0, {}};
                    w->actions.push_back(WaitAction{*s, false});
                } else if (a.func == QLatin1String("rotateYaw")) {
                    const auto h = paramNumber(a, "aircraftHeading");
                    if (!h)
                        return MissionError{QStringLiteral("%1: rotateYaw without an aircraftHeading").arg(where), file, byIndex[i]->line, 0, {}};
                    w->actions.push_back(HeadingAction{*h < 0.0 ? *h + 360.0 : *h, false});
                } else if (a.func == QLatin1String("gimbalRotate")) {
                    // Each angle counts where its enable flag is 1; WPML's pitch -90° is UgCS's tilt 90°.
                    const auto enabled = [&a](const char *flag) { return paramNumber(a, flag).value_or(0) == 1; };
                    CameraControlAction gimbal;
                    if (enabled("gimbalPitchRotateEnable")) {
                        if (const auto pitch = paramNumber(a, "gimbalPitchRotateAngle")) gimbal.tiltDeg = -*pitch;
                    }
                    if (enabled("gimbalRollRotateEnable")) gimbal.rollDeg = paramNumber(a, "gimbalRollRotateAngle");
                    if (enabled("gimbalYawRotateEnable")) gimbal.yawDeg = paramNumber(a, "gimbalYawRotateAngle");
                    if (gimbal == CameraControlAction{})
                        *notices << QStringLiteral("%1: a gimbalRotate that turns nothing is not kept").arg(where);
                    else
                        w->actions.push_back(gimbal);
                } else {
                    *notices << QStringLiteral("%1: the WPML action \"%2\" has no Sortie equivalent and is not kept").arg(where, a.func);
                }
            }
        }
    }

    if (doc.finishAction == QLatin1String("goHome")) {
        route.settings.endAction = EndAction::ReturnHome;
    } else if (doc.finishAction == QLatin1String("autoLand")) {
        asWaypoint(route.segments.back())->role = WaypointRole::Land;
    } else if (doc.finishAction == QLatin1String("gotoFirstWaypoint")) {
        *notices << QStringLiteral("the route ends by flying back to its first waypoint; Sortie's route ends at its last waypoint");
    }
    return route;
}

} // namespace

Result<WpmlImport> readWpml(const QByteArray &data)
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
    const Result<ReadDocument> doc = DocumentReader(waylines, waylinesName).read();
    if (!doc)
        return doc.error();
    std::optional<ReadDocument> templ;
    if (!templateKml.isEmpty()) {
        Result<ReadDocument> t = DocumentReader(templateKml, QStringLiteral("wpmz/template.kml")).read();
        if (!t)
            return t.error();
        templ = std::move(t).value();
    }
    if (doc->folders.empty())
        return MissionError{QStringLiteral("no wayline (Folder) in the document"), waylinesName, 0, 0, {}};
    WpmlImport out;
    for (const DjiDroneModel &m : djiDroneModels())
        if (doc->droneEnum == m.droneEnumValue && doc->droneSubEnum.value_or(0) == m.droneSubEnumValue)
            out.droneName = m.name;
    for (size_t f = 0; f < doc->folders.size(); ++f) {
        const ReadFolder *tf = templ && doc->folders.size() == 1 && !templ->folders.empty() ? &templ->folders.front() : nullptr;
        Result<Route> r = routeOf(doc->folders[f], tf, *doc, waylinesName, &out.notices);
        if (!r)
            return r.error();
        Route route = std::move(r).value();
        route.settings.profile.name = out.droneName;
        if (doc->folders.size() > 1)
            route.settings.name = QStringLiteral("Wayline %1").arg(f + 1);
        out.routes.push_back(std::move(route));
    }
    out.notices.removeDuplicates();
    return out;
}

} // namespace sortie::mission::formats
