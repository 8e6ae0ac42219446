#include "SortieFormat.h"

#include "SegmentParameters.h"

#include "Domain.pb.h"
#include "HciOrigin.h"
#include "JsonCursor.h"
#include "QgcFenceJson.h"
#include "SortieActionJson.h"
#include "SortieMigrations.h"
#include <QCoreApplication>

namespace sortie::mission::formats {

namespace pb = com::ugcs::ucs::proto;

namespace {
std::string str(const QString &s) { return s.toStdString(); }

const char *const kReasons[] = {"rcLost", "gpsLost", "lowBattery", "datalinkLost"};
const char *const kActions[] = {"goHome", "land", "wait", "continue", "notAvailable"};

// The server's own message, kept as the base64 of its bytes under "hci".
template<typename Message>
void putHci(Json &j, const Message *m)
{
    if (m)
        j["hci"] = QByteArray::fromStdString(m->SerializeAsString()).toBase64().toStdString();
}

template<typename Message>
std::optional<Message> takeHci(const JsonCursor &c)
{
    const auto h = c.find("hci");
    if (!h)
        return std::nullopt;
    Message m;
    const QByteArray bytes = QByteArray::fromBase64(h->string().toLatin1(), QByteArray::AbortOnBase64DecodingErrors);
    if (bytes.isEmpty() || !m.ParseFromArray(bytes.constData(), int(bytes.size())))
        h->fail(QCoreApplication::translate("SortieFormat", "not a valid UgCS %1").arg(QString::fromStdString(Message::descriptor()->name())));
    return m;
}

template<typename Message>
ServerOrigin takeOrigin(const JsonCursor &c)
{
    std::optional<Message> m = takeHci<Message>(c);
    return m ? hciOrigin(std::move(*m)) : ServerOrigin();
}


const std::string kNone;

AltitudeType altitudeTypeAt(const JsonCursor &c, const char *key)
{
    const std::string &v = c.text(key, kNone);
    if (v == "AGL")
        return AltitudeType::Agl;
    if (v == "AMSL")
        return AltitudeType::Amsl;
    c.failAt(key, v.empty() ? QCoreApplication::translate("SortieFormat", "missing \"AGL\" or \"AMSL\"") : QCoreApplication::translate("SortieFormat", "expected \"AGL\" or \"AMSL\""));
}

// Enum names are compared as UTF-8 bytes: no QString per field on the hot path of a big file.
template<typename E, size_t N>
E enumAt(const JsonCursor &c, const char *key, const char *fallback, const std::pair<const char *, E> (&names)[N])
{
    static const std::string none;
    const std::string &v = c.text(key, none);
    const std::string_view s = v.empty() && !c.find(key) ? std::string_view(fallback) : std::string_view(v);
    for (const auto &[name, value] : names)
        if (s == name)
            return value;
    c.failAt(key, QCoreApplication::translate("SortieFormat", "unknown value \"%1\"").arg(QString::fromStdString(v)));
}

constexpr std::pair<const char *, WaypointRole> kRoles[] = {
    {"waypoint", WaypointRole::Pass}, {"takeoff", WaypointRole::Takeoff}, {"land", WaypointRole::Land}};
constexpr std::pair<const char *, TurnType> kTurns[] = {
    {"StopAndTurn", TurnType::StopAndTurn}, {"Straight", TurnType::Straight}, {"Spline", TurnType::Spline}, {"BankTurn", TurnType::BankTurn}};

Json cameraJson(const Camera &c)
{
    Json j{{"name", str(c.name)}, {"sensorWidthMm", c.sensorWidthMm}, {"sensorHeightMm", c.sensorHeightMm},
           {"focalLengthMm", c.focalLengthMm}, {"imageWidthPx", c.imageWidthPx}, {"imageHeightPx", c.imageHeightPx}};
    if (c.minTriggerIntervalS > 0)  // absent: not known
        j["minTriggerIntervalS"] = c.minTriggerIntervalS;
    return j;
}

Camera readCamera(const JsonCursor &cam)
{
    Camera c;
    c.name = cam.stringOr("name", QString());
    c.sensorWidthMm = cam.number("sensorWidthMm");
    c.sensorHeightMm = cam.number("sensorHeightMm");
    c.focalLengthMm = cam.number("focalLengthMm");
    c.imageWidthPx = cam.at("imageWidthPx").integer();
    c.imageHeightPx = cam.at("imageHeightPx").integer();
    c.minTriggerIntervalS = cam.numberOr("minTriggerIntervalS", 0.0);
    return c;
}

Json profileCamerasJson(const std::vector<ProfileCamera> &cameras)
{
    Json out = Json::array();
    for (const ProfileCamera &c : cameras) {
        Json j = cameraJson(c.camera);
        j["id"] = c.id;
        out.push_back(std::move(j));
    }
    return out;
}

std::vector<ProfileCamera> readProfileCameras(const JsonCursor &list)
{
    std::vector<ProfileCamera> out;
    for (size_t i = 0; i < list.arraySize(); ++i) {
        const JsonCursor c = list.at(i);
        out.push_back({c.integerOr("id", 0), readCamera(c)});
    }
    return out;
}

Json segmentJson(const Segment &s)
{
    if (const Waypoint *w = asWaypoint(s)) {
        Json j{{"type", "waypoint"}, {"role", str(roleName(w->role))}, {"latitude", w->position.latitude},
               {"longitude", w->position.longitude}, {"altitude", w->altitude}, {"altitudeType", str(altitudeTypeName(w->altitudeType))},
               {"speed", w->speed}, {"turnType", str(turnTypeName(w->turnType))}, {"acceptanceRadius", w->acceptanceRadius}};
        if (!w->actions.empty()) {
            Json actions = Json::array();
            for (const auto &a : w->actions)
                actions.push_back(actionJson(a));
            j["actions"] = std::move(actions);
        }
        putHci(j, hciSegment(w->origin));
        return j;
    }
    if (const AlgorithmSegment *a = asAlgorithmSegment(s)) {
        Json points = Json::array();
        for (const FigurePoint &p : a->points)
            points.push_back({p.position.latitude, p.position.longitude, p.altitude, str(altitudeTypeName(p.altitudeType))});
        Json parameters = Json::array();  // pairs, in order: names may repeat on the wire
        for (const ParameterValue &v : a->parameters)
            parameters.push_back({str(v.name), str(v.value)});
        Json j{{"type", "algorithm"}, {"algorithm", str(a->algorithm)}, {"figure", int(a->figure)}, {"points", std::move(points)},
               {"figureParameters", a->figureParameters}, {"parameters", std::move(parameters)}};
        if (!a->actions.empty()) {
            Json actions = Json::array();
            for (const auto &action : a->actions)
                actions.push_back(actionJson(action));
            j["actions"] = std::move(actions);
        }
        putHci(j, hciSegment(a->origin));
        return j;
    }
    const AreaScan &scan = std::get<AreaScan>(s);
    const AreaScanParameters &p = scan.parameters;
    Json polygon = Json::array();
    for (const GeoPoint &g : scan.polygon)
        polygon.push_back({g.latitude, g.longitude});
    // Parameters by their UgCS wire names and units (schema 3), read back through SegmentParameters.
    Json j{{"type", "areaScan"}, {"polygon", std::move(polygon)},
           {"camera", cameraJson(p.camera)},
           {"heightMode", p.heightMode == ScanHeightMode::Altitude ? "altitude" : "groundSampleDistance"},
           {"parameters", {{"height", p.altitude}, {"groundSampleDistance", p.groundSampleDistanceCm},
                           {"altitudeType", str(altitudeTypeName(p.altitudeType))}, {"overlapForward", p.frontOverlapPercent},
                           {"overlapSide", p.sideOverlapPercent}, {"sideDistance", p.sideDistanceMeters},
                           {"directionAngle", p.directionDeg}, {"overshoot", p.turnaroundMeters}, {"speed", p.speed}}}};
    if (p.toleranceMeters)
        j["parameters"]["tolerance"] = *p.toleranceMeters;
    putHci(j, hciSegment(scan.origin));
    return j;
}

// One area-scan parameter from the file through the one reader; a bad value names its place.
void setParameter(const JsonCursor &params, Segment &segment, const char *name, bool required)
{
    const auto v = params.find(name);
    if (!v) {
        if (required)
            params.failAt(name, QStringLiteral("missing"));
        return;
    }
    const QVariant value = v->value().is_string() ? QVariant(v->string()) : QVariant(v->number());
    QString error;
    if (!setParameterValue(segment, QString::fromLatin1(name), value, &error))
        v->fail(error);
}

Segment readSegment(const JsonCursor &c)
{
    c.requireObject();
    const std::string &type = c.text("type", kNone);
    if (type == "waypoint") {
        Waypoint w;
        w.role = enumAt(c, "role", "waypoint", kRoles);
        w.position = {c.number("latitude"), c.number("longitude")};
        if (!(w.position.latitude >= -90 && w.position.latitude <= 90))
            c.failAt("latitude", QCoreApplication::translate("SortieFormat", "latitude out of range"));
        if (!w.position.isValid())
            c.failAt("longitude", QCoreApplication::translate("SortieFormat", "longitude out of range"));
        w.altitude = c.number("altitude");
        w.altitudeType = altitudeTypeAt(c, "altitudeType");
        w.speed = c.number("speed");
        w.turnType = enumAt(c, "turnType", "StopAndTurn", kTurns);
        w.acceptanceRadius = c.numberOr("acceptanceRadius", 0);
        if (const auto actions = c.find("actions"))
            for (size_t i = 0; i < actions->arraySize(); ++i)
                w.actions.push_back(readAction(actions->at(i)));
        w.origin = takeOrigin<pb::SegmentDefinition>(c);
        return w;
    }
    if (type == "areaScan") {
        AreaScan s;
        const JsonCursor polygon = c.at("polygon");
        for (size_t i = 0; i < polygon.arraySize(); ++i) {
            const JsonCursor v = polygon.at(i);
            const GeoPoint g{v.at(size_t(0)).number(), v.at(size_t(1)).number()};
            if (!g.isValid())
                v.fail(QCoreApplication::translate("SortieFormat", "latitude/longitude out of range"));
            s.polygon.push_back(g);
        }
        AreaScanParameters &p = s.parameters;
        p.camera = readCamera(c.at("camera"));
        const QString mode = c.stringOr("heightMode", QStringLiteral("altitude"));
        if (mode != QLatin1String("altitude") && mode != QLatin1String("groundSampleDistance"))
            c.at("heightMode").fail(QCoreApplication::translate("SortieFormat", "expected \"altitude\" or \"groundSampleDistance\""));
        // The one parameter reader; the height mode's own value goes last, since it sets the mode.
        Segment segment = std::move(s);
        const JsonCursor params = c.at("parameters");
        params.requireObject();
        for (const char *name : {"altitudeType", "overlapForward", "overlapSide", "sideDistance", "directionAngle", "overshoot", "speed", "tolerance"})
            setParameter(params, segment, name, name == std::string_view("altitudeType") || name == std::string_view("speed"));
        // The other of height and GSD is derived from this one and the camera.
        const char *last = mode == QLatin1String("altitude") ? "height" : "groundSampleDistance";
        setParameter(params, segment, last, true);
        AreaScan &scan = std::get<AreaScan>(segment);
        scan.origin = takeOrigin<pb::SegmentDefinition>(c);
        return segment;
    }
    if (type == "algorithm") {
        AlgorithmSegment a;
        a.algorithm = c.at("algorithm").string();
        const int figure = c.at("figure").integer();
        if (figure < 0 || figure > int(FigureType::Polyline))
            c.at("figure").fail(QCoreApplication::translate("SortieFormat", "no figure type %1").arg(figure));
        a.figure = FigureType(figure);
        const JsonCursor points = c.at("points");
        for (size_t i = 0; i < points.arraySize(); ++i) {
            const JsonCursor p = points.at(i);
            FigurePoint fp;
            fp.position = {p.at(size_t(0)).number(), p.at(size_t(1)).number()};
            if (!fp.position.isValid())
                p.fail(QCoreApplication::translate("SortieFormat", "latitude/longitude out of range"));
            fp.altitude = p.at(size_t(2)).number();
            const QString type = p.at(size_t(3)).string();
            if (!parseAltitudeType(type, &fp.altitudeType))
                p.at(size_t(3)).fail(QCoreApplication::translate("SortieFormat", "expected \"AGL\" or \"AMSL\""));
            a.points.push_back(fp);
        }
        const JsonCursor figureParameters = c.at("figureParameters");
        for (size_t i = 0; i < figureParameters.arraySize(); ++i)
            a.figureParameters.push_back(figureParameters.at(i).number());
        const JsonCursor parameters = c.at("parameters");
        for (size_t i = 0; i < parameters.arraySize(); ++i) {
            const JsonCursor pair = parameters.at(i);
            a.parameters.push_back({pair.at(size_t(0)).string(), pair.at(size_t(1)).string()});
        }
        if (const auto actions = c.find("actions"))
            for (size_t i = 0; i < actions->arraySize(); ++i)
                a.actions.push_back(readAction(actions->at(i)));
        a.origin = takeOrigin<pb::SegmentDefinition>(c);
        return a;
    }
    c.failAt("type", QCoreApplication::translate("SortieFormat", "unknown segment type \"%1\"").arg(QString::fromStdString(type)));
}

Json routeJson(const Route &r)
{
    const RouteSettings &s = r.settings;
    Json failsafes = Json::array();
    for (const Failsafe &f : s.failsafes)
        failsafes.push_back({{"reason", kReasons[int(f.reason)]}, {"action", kActions[int(f.action)]}});
    Json j{{"name", str(s.name)},
           {"vehicleProfile", {{"name", str(s.profile.name)}, {"maxHorizontalSpeed", s.profile.maxHorizontalSpeed},
                               {"climbRate", s.profile.climbRate}, {"descentRate", s.profile.descentRate},
                               {"safeTerrainDistance", s.profile.safeTerrainDistance}, {"cameras", profileCamerasJson(s.profile.cameras)}}},
           {"safeAltitude", s.safeAltitude}, {"maxAltitude", s.maxAltitude}, {"initialSpeed", s.initialSpeed},
           {"maxSpeed", s.maxSpeed}, {"cornerRadius", s.cornerRadius}, {"takeoffHeight", s.takeoffHeight},
           {"failsafes", std::move(failsafes)}, {"endAction", s.endAction == EndAction::ReturnHome ? "returnHome" : "none"},
           {"checkAerodromeNfz", s.checkAerodromeNfz}, {"checkCustomNfz", s.checkCustomNfz}};
    if (s.plannedStart)
        j["plannedStart"] = str(s.plannedStart->toUTC().toString(Qt::ISODateWithMs));
    if (!s.authorisations.empty()) {
        Json authorisations = Json::object();
        for (const auto &[identifier, reference] : s.authorisations)
            authorisations[identifier.toStdString()] = str(reference);
        j["authorisations"] = std::move(authorisations);
    }
    if (s.home)
        j["home"] = {{"latitude", s.home->position.latitude}, {"longitude", s.home->position.longitude}, {"altitudeAmsl", s.home->altitudeAmsl}};
    if (!r.fence.empty())  // a .plan's geofence and rally points, in the .plan's own form
        j["fence"] = {{"geoFence", geoFenceJson(r.fence)}, {"rallyPoints", rallyPointsJson(r.fence)}};
    putHci(j, hciRoute(r.origin));
    Json segments = Json::array();
    for (const Segment &seg : r.segments)
        segments.push_back(segmentJson(seg));
    j["segments"] = std::move(segments);
    return j;
}

Route readRoute(const JsonCursor &c)
{
    c.requireObject();
    Route r;
    RouteSettings &s = r.settings;
    s.name = c.stringOr("name", QString());
    if (const auto p = c.find("vehicleProfile")) {
        s.profile.name = p->stringOr("name", QString());
        s.profile.maxHorizontalSpeed = p->numberOr("maxHorizontalSpeed", 0);
        s.profile.climbRate = p->numberOr("climbRate", s.profile.climbRate);
        s.profile.descentRate = p->numberOr("descentRate", s.profile.descentRate);
        s.profile.safeTerrainDistance = p->numberOr("safeTerrainDistance", s.profile.safeTerrainDistance);
        if (const auto cameras = p->find("cameras"))
            s.profile.cameras = readProfileCameras(*cameras);
    }
    s.safeAltitude = c.numberOr("safeAltitude", s.safeAltitude);
    s.maxAltitude = c.numberOr("maxAltitude", s.maxAltitude);
    s.initialSpeed = c.numberOr("initialSpeed", s.initialSpeed);
    s.maxSpeed = c.numberOr("maxSpeed", s.maxSpeed);
    s.cornerRadius = c.numberOr("cornerRadius", 0);
    s.takeoffHeight = c.numberOr("takeoffHeight", 0);
    if (const auto f = c.find("failsafes"))
        for (size_t i = 0; i < f->arraySize(); ++i)
            s.failsafes.push_back({FailsafeReason(indexOf(kReasons, f->at(i).at("reason"))), FailsafeAction(indexOf(kActions, f->at(i).at("action")))});
    const QString end = c.stringOr("endAction", QStringLiteral("none"));
    if (end != QLatin1String("none") && end != QLatin1String("returnHome"))
        c.at("endAction").fail(QCoreApplication::translate("SortieFormat", "expected \"none\" or \"returnHome\""));
    s.endAction = end == QLatin1String("returnHome") ? EndAction::ReturnHome : EndAction::None;
    // Files written before the flags existed: off, as the server reads an absent flag.
    s.checkAerodromeNfz = c.booleanOr("checkAerodromeNfz", false);
    s.checkCustomNfz = c.booleanOr("checkCustomNfz", false);
    if (const auto start = c.find("plannedStart")) {
        const QString text = start->string();
        QDateTime when = QDateTime::fromString(text, Qt::ISODateWithMs);
        if (!when.isValid() || !text.contains(QLatin1Char('T')) || when.timeSpec() == Qt::LocalTime)
            start->fail(QCoreApplication::translate("SortieFormat", "expected a date and time in UTC, e.g. 2026-06-06T18:00:00Z"));
        s.plannedStart = when.toUTC();
    }
    if (const auto a = c.find("authorisations")) {
        a->requireObject();
        for (const auto &[identifier, reference] : a->value().items()) {
            const QString id = QString::fromStdString(identifier).trimmed();
            if (id.isEmpty())
                a->fail(QCoreApplication::translate("SortieFormat", "an authorisation needs the zone's identifier"));
            s.authorisations[id] = a->at(identifier.c_str()).string();
        }
    }
    if (const auto h = c.find("home"))
        s.home = HomePosition{{h->number("latitude"), h->number("longitude")}, h->number("altitudeAmsl")};
    if (const auto f = c.find("fence")) {
        QStringList problems;  // Sortie wrote it: a bad part is an error, not a notice
        r.fence = fenceFromPlanJson(*f, &problems);
        if (!problems.isEmpty())
            f->fail(problems.front());
    }
    r.origin = takeOrigin<pb::Route>(c);
    const JsonCursor segments = c.at("segments");
    const size_t n = segments.arraySize();
    r.segments.reserve(n);
    for (size_t i = 0; i < n; ++i)
        r.segments.push_back(readSegment(segments.at(i)));
    return r;
}
}

namespace {
// Pretty-printed, except that each segment is one compact line: diffs show the waypoints that
// changed, and the file is a third smaller (and faster to read) than fully indented JSON.
void writePretty(std::string &out, const Json &v, int depth, bool compactChildren)
{
    const std::string pad(size_t(depth + 1), ' '), closePad(size_t(depth), ' ');
    if (v.is_object() && !v.empty()) {
        out += "{\n";
        size_t i = 0;
        for (auto it = v.begin(); it != v.end(); ++it, ++i) {
            out += pad + Json(it.key()).dump() + ": ";
            writePretty(out, it.value(), depth + 1, it.key() == "segments");
            out += i + 1 < v.size() ? ",\n" : "\n";
        }
        out += closePad + "}";
    } else if (v.is_array() && !v.empty() && (compactChildren || v.front().is_object())) {
        out += "[\n";
        for (size_t i = 0; i < v.size(); ++i) {
            out += pad;
            if (compactChildren)
                out += v[i].dump();
            else
                writePretty(out, v[i], depth + 1, false);
            out += i + 1 < v.size() ? ",\n" : "\n";
        }
        out += closePad + "]";
    } else {
        out += v.dump();
    }
}
}

QByteArray writeSortie(const Mission &mission)
{
    Json routes = Json::array();
    for (const Route &r : mission.routes)
        routes.push_back(routeJson(r));
    Json m{{"name", str(mission.name)}, {"description", str(mission.description)}};
    putHci(m, hciMission(mission.origin));
    m["routes"] = std::move(routes);
    const Json doc{{"format", "sortie-mission"}, {"schemaVersion", kSortieSchemaVersion}, {"mission", std::move(m)}};
    std::string out;
    writePretty(out, doc, 0, false);
    out += '\n';
    return QByteArray::fromStdString(out);
}

Result<Mission> readSortie(const QByteArray &data)
{
    Result<Json> parsed = parseJson(data);
    if (!parsed)
        return parsed.error();
    Json doc = std::move(parsed).value();
    try {
        const JsonCursor root(doc);
        root.requireObject();
        if (root.stringOr("format", QString()) != QLatin1String("sortie-mission"))
            root.fail(QCoreApplication::translate("SortieFormat", "not a Sortie mission file (\"format\" is not \"sortie-mission\")"));
        const int version = root.at("schemaVersion").integer();
        if (version < 1)
            root.at("schemaVersion").fail(QCoreApplication::translate("SortieFormat", "schema version %1 does not exist").arg(version));
        if (version > kSortieSchemaVersion)
            root.at("schemaVersion").fail(QCoreApplication::translate("SortieFormat", "written by a newer Sortie (schema %1); this one reads up to schema %2")
                                             .arg(version).arg(kSortieSchemaVersion));
        if (version < kSortieSchemaVersion)
            migrateSortie(doc, version);
        const JsonCursor m = JsonCursor(doc).at("mission");
        Mission mission;
        mission.name = m.stringOr("name", QString());
        mission.description = m.stringOr("description", QString());
        mission.origin = takeOrigin<pb::Mission>(m);
        const JsonCursor routes = m.at("routes");
        for (size_t i = 0; i < routes.arraySize(); ++i)
            mission.routes.push_back(readRoute(routes.at(i)));
        return mission;
    } catch (const JsonPathError &e) {
        return errorAt(e);
    }
}

} // namespace sortie::mission::formats
