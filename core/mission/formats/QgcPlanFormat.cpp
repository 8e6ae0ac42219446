#include "QgcPlanFormat.h"

#include "QgcFenceJson.h"
#include "QgcSurveyJson.h"

#include "AlgorithmCatalog.h"
#include "ScanPlanCache.h"
#include "SegmentPlanning.h"

#include <cmath>
#include <limits>
#include <QCoreApplication>

namespace sortie::mission::formats {

namespace {
constexpr int kMavTypeFixedWing = 1;
constexpr int kMavTypeQuadrotor = 2;

double paramOrNan(const JsonCursor &c)
{
    return c.isNull() ? std::numeric_limits<double>::quiet_NaN() : c.number();
}

MavlinkItem simpleFromJson(const JsonCursor &item)
{
    MavlinkItem m;
    m.command = item.at("command").integer();
    m.frame = item.at("frame").integer();
    m.autoContinue = item.booleanOr("autoContinue", true);
    m.jsonPath = item.pathText();
    const JsonCursor params = item.at("params");
    const size_t n = params.arraySize();
    if (n != 7 && n != 4)
        params.fail(QCoreApplication::translate("QgcPlanFormat", "expected 7 params (or 4 and a \"coordinate\"), found %1").arg(n));
    for (size_t i = 0; i < 4; ++i) {
        const double v = paramOrNan(params.at(i));
        m.param[i] = std::isnan(v) ? 0.0 : v;  // QGroundControl writes unset params as null
    }
    if (n == 7) {
        m.latitude = paramOrNan(params.at(4));
        m.longitude = paramOrNan(params.at(5));
        m.altitude = paramOrNan(params.at(6));
    } else {
        const JsonCursor coordinate = item.at("coordinate");
        m.latitude = coordinate.at(size_t(0)).number();
        m.longitude = coordinate.at(size_t(1)).number();
        m.altitude = coordinate.at(size_t(2)).number();
    }
    if (std::isnan(m.altitude))
        m.altitude = 0;
    return m;
}

Json itemToJson(const MavlinkItem &i, int jumpId)
{
    // DO commands carry no position: QGroundControl writes their lat/lon/alt as 0.
    return Json{{"autoContinue", i.autoContinue}, {"command", i.command}, {"doJumpId", jumpId}, {"frame", i.frame},
                {"params", {i.param[0], i.param[1], i.param[2], i.param[3], i.latitude, i.longitude, i.altitude}},
                {"type", "SimpleItem"}};
}
}

Result<ImportedRoute> readQgcPlan(const QByteArray &data)
{
    Result<Json> parsed = parseJson(data);
    if (!parsed)
        return parsed.error();
    const Json &doc = parsed.value();
    try {
        const JsonCursor root(doc);
        root.requireObject();
        if (root.at("fileType").string() != QLatin1String("Plan"))
            root.at("fileType").fail(QCoreApplication::translate("QgcPlanFormat", "not a QGroundControl plan (fileType is not \"Plan\")"));
        if (const int v = root.at("version").integer(); v != 1)
            root.at("version").fail(QCoreApplication::translate("QgcPlanFormat", "plan version %1 is not supported (Sortie reads version 1)").arg(v));
        const JsonCursor mission = root.at("mission");
        if (const int v = mission.at("version").integer(); v != 2)
            mission.at("version").fail(QCoreApplication::translate("QgcPlanFormat", "mission version %1 is not supported (Sortie reads version 2)").arg(v));
        std::optional<HomePosition> home;
        if (const auto h = mission.find("plannedHomePosition")) {
            home = HomePosition{{h->at(size_t(0)).number(), h->at(size_t(1)).number()}, h->at(size_t(2)).number()};
            if (!home->position.isValid())
                h->fail(QCoreApplication::translate("QgcPlanFormat", "the planned home position is out of range"));
        }
        const bool fixedWing = mission.integerOr("vehicleType", kMavTypeQuadrotor) == kMavTypeFixedWing;
        double speed = fixedWing ? mission.numberOr("cruiseSpeed", 0) : mission.numberOr("hoverSpeed", 0);
        if (!(speed > 0))
            speed = mission.numberOr("cruiseSpeed", 5.0) > 0 ? mission.numberOr("cruiseSpeed", 5.0) : 5.0;

        QStringList notices;
        std::vector<MavlinkItem> items;
        const JsonCursor list = mission.at("items");
        for (size_t i = 0; i < list.arraySize(); ++i) {
            const JsonCursor item = list.at(i);
            const QString type = item.at("type").string();
            if (type == QLatin1String("SimpleItem")) {
                items.push_back(simpleFromJson(item));
            } else if (type == QLatin1String("ComplexItem")) {
                const QString kind = item.at("complexItemType").string();
                MavlinkItem m;
                m.jsonPath = item.pathText();
                if (kind == QLatin1String("survey"))
                    m.scan = std::make_shared<const AreaScan>(surveyFromJson(item, &notices));
                else if (kind == QLatin1String("CorridorScan"))
                    m.segment = std::make_shared<const AlgorithmSegment>(corridorFromJson(item, &notices));
                else if (kind == QLatin1String("StructureScan"))
                    m.segment = std::make_shared<const AlgorithmSegment>(structureScanFromJson(item, &notices));
                else
                    item.at("complexItemType").fail(QCoreApplication::translate("QgcPlanFormat", "complex item \"%1\" is not supported; Sortie imports surveys, corridor and structure scans").arg(kind));
                items.push_back(std::move(m));
            } else {
                item.at("type").fail(QCoreApplication::translate("QgcPlanFormat", "unknown item type \"%1\"").arg(type));
            }
        }
        RouteFence fence = fenceFromPlanJson(root, &notices);

        Result<ImportedRoute> route = routeFromMavlink(items, home, speed);
        if (!route)
            return route;
        ImportedRoute out = std::move(route).value();
        out.route.fence = std::move(fence);
        out.notices = notices + out.notices;
        return out;
    } catch (const JsonPathError &e) {
        return errorAt(e);
    }
}

QByteArray writeQgcPlan(const Route &route, QStringList *notices, ScanPlanCache *cache)
{
    const double speed = route.settings.initialSpeed;
    MavlinkExport out = routeToMavlink(route, speed, cache, /*keepScans=*/true);
    Json items = Json::array();
    int jumpId = 1;
    for (const MavlinkItem &i : out.items) {
        if (i.segment) {
            const SegmentPlanOutcome o = planAlgorithmSegment(*i.segment, AlgorithmCatalog::builtIn(), planContextOf(route.settings));
            if (!o.ok()) {
                out.notices << QCoreApplication::translate("QgcPlanFormat", "A corridor was left out: %1").arg(o.errors.empty() ? QString() : o.errors.front());
                continue;
            }
            int used = 0;
            items.push_back(corridorToJson(*i.segment, *o.plan, jumpId, &used));
            jumpId += used;
            continue;
        }
        if (!i.scan) {
            items.push_back(itemToJson(i, jumpId++));
            continue;
        }
        AreaScanOutcome scratch;
        const AreaScanOutcome &o = scanOutcome(*i.scan, cache, scratch);
        if (!o.ok()) {
            out.notices << QCoreApplication::translate("QgcPlanFormat", "An area scan was left out: %1").arg(o.message);
            continue;
        }
        int used = 0;
        items.push_back(surveyToJson(*i.scan, *o.plan, jumpId, &used));
        jumpId += used;
    }
    HomePosition home;
    if (route.settings.home) {
        home = *route.settings.home;
    } else {
        if (!route.segments.empty())
            home.position = anchorOf(route.segments.front());
        out.notices.prepend(QCoreApplication::translate("QgcPlanFormat", "The route has no home position: the first point was written as home, at 0 m AMSL."));
    }
    const Json doc{
        {"fileType", "Plan"},
        {"geoFence", geoFenceJson(route.fence)},
        {"groundStation", "Sortie"},
        {"mission", {{"cruiseSpeed", speed}, {"firmwareType", 0}, {"hoverSpeed", speed}, {"items", std::move(items)},
                     {"plannedHomePosition", {home.position.latitude, home.position.longitude, home.altitudeAmsl}},
                     {"vehicleType", kMavTypeQuadrotor}, {"version", 2}}},
        {"rallyPoints", rallyPointsJson(route.fence)},
        {"version", 1}};
    if (notices)
        *notices << out.notices;
    return QByteArray::fromStdString(doc.dump(4)) + '\n';
}

Result<RouteFence> readQgcPlanFence(const QByteArray &data, QStringList *notices)
{
    Result<Json> parsed = parseJson(data);
    if (!parsed)
        return parsed.error();
    try {
        const JsonCursor root(parsed.value());
        root.requireObject();
        if (root.at("fileType").string() != QLatin1String("Plan"))
            root.at("fileType").fail(QCoreApplication::translate("QgcPlanFormat", "not a QGroundControl plan (fileType is not \"Plan\")"));
        return fenceFromPlanJson(root, notices);
    } catch (const JsonPathError &e) {
        return errorAt(e);
    }
}

} // namespace sortie::mission::formats
