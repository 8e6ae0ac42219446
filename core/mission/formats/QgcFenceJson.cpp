#include "QgcFenceJson.h"
#include <QCoreApplication>

namespace sortie::mission::formats {

namespace {
GeoPoint latLon(const JsonCursor &pair)
{
    if (pair.arraySize() < 2)
        pair.fail(QCoreApplication::translate("QgcFenceJson", "expected [latitude, longitude]"));
    const GeoPoint p{pair.at(size_t(0)).number(), pair.at(size_t(1)).number()};
    if (!p.isValid())
        pair.fail(QCoreApplication::translate("QgcFenceJson", "latitude or longitude out of range"));
    return p;
}

FencePoint pointWithAltitude(const JsonCursor &c)
{
    if (c.arraySize() != 3)
        c.fail(QCoreApplication::translate("QgcFenceJson", "expected [latitude, longitude, altitude]"));
    return {latLon(c), c.at(size_t(2)).number()};
}

// Reads each element of an array section with `read`, leaving out (with a notice) what fails.
template<typename Read>
// `oneLeftOut` and `allLeftOut` are whole sentences ("%1" the JSON path, "%2" the reason), so that a
// translation words the kind of thing with its own grammar.
void eachOf(const JsonCursor &section, const char *key, QStringList *notices, const QString &oneLeftOut, const QString &allLeftOut, Read read)
{
    const auto list = section.find(key);
    if (!list || list->isNull())
        return;
    try {
        for (size_t i = 0; i < list->arraySize(); ++i) {
            try {
                read(list->at(i));
            } catch (const JsonPathError &e) {
                if (notices)
                    *notices << oneLeftOut.arg(QString::fromStdString(e.path), e.message);
            }
        }
    } catch (const JsonPathError &e) {
        if (notices)
            *notices << allLeftOut.arg(QString::fromStdString(e.path), e.message);
    }
}
} // namespace

RouteFence fenceFromPlanJson(const JsonCursor &root, QStringList *notices)
{
    RouteFence fence;
    if (const auto geo = root.find("geoFence"); geo && !geo->isNull()) {
        eachOf(*geo, "polygons", notices, QCoreApplication::translate("QgcFenceJson", "Geofence polygon at %1 was left out: %2"),
               QCoreApplication::translate("QgcFenceJson", "The geofence polygons at %1 were left out: %2"), [&](const JsonCursor &c) {
            FencePolygon p;
            p.inclusion = c.booleanOr("inclusion", true);
            const JsonCursor ring = c.at("polygon");
            for (size_t k = 0; k < ring.arraySize(); ++k)
                p.vertices.push_back(latLon(ring.at(k)));
            if (p.vertices.size() < 3)
                ring.fail(QCoreApplication::translate("QgcFenceJson", "a polygon needs at least 3 vertices, found %1").arg(p.vertices.size()));
            fence.polygons.push_back(std::move(p));
        });
        // Version 1 had one inclusion polygon, "polygon": [[lat, lon], ...].
        if (const auto old = geo->find("polygon"); old && old->value().is_array() && !old->value().empty()) {
            try {
                FencePolygon p;
                for (size_t k = 0; k < old->arraySize(); ++k)
                    p.vertices.push_back(latLon(old->at(k)));
                if (p.vertices.size() < 3)
                    old->fail(QCoreApplication::translate("QgcFenceJson", "a polygon needs at least 3 vertices, found %1").arg(p.vertices.size()));
                fence.polygons.push_back(std::move(p));
            } catch (const JsonPathError &e) {
                if (notices)
                    *notices << QCoreApplication::translate("QgcFenceJson", "Geofence polygon at %1 was left out: %2").arg(QString::fromStdString(e.path), e.message);
            }
        }
        eachOf(*geo, "circles", notices, QCoreApplication::translate("QgcFenceJson", "Geofence circle at %1 was left out: %2"),
               QCoreApplication::translate("QgcFenceJson", "The geofence circles at %1 were left out: %2"), [&](const JsonCursor &c) {
            FenceCircle circle;
            circle.inclusion = c.booleanOr("inclusion", true);
            const JsonCursor shape = c.at("circle");
            circle.center = latLon(shape.at("center"));
            circle.radius = shape.number("radius");
            if (!(circle.radius > 0))
                shape.failAt("radius", QCoreApplication::translate("QgcFenceJson", "the radius must be positive metres"));
            fence.circles.push_back(circle);
        });
        if (const auto back = geo->find("breachReturn"); back && !back->isNull()) {
            try {
                fence.breachReturn = pointWithAltitude(*back);
            } catch (const JsonPathError &e) {
                if (notices)
                    *notices << QCoreApplication::translate("QgcFenceJson", "The geofence's breach return point at %1 was left out: %2").arg(QString::fromStdString(e.path), e.message);
            }
        }
    }
    if (const auto rally = root.find("rallyPoints"); rally && !rally->isNull())
        eachOf(*rally, "points", notices, QCoreApplication::translate("QgcFenceJson", "Rally point at %1 was left out: %2"),
               QCoreApplication::translate("QgcFenceJson", "The rally points at %1 were left out: %2"),
               [&](const JsonCursor &c) { fence.rallyPoints.push_back(pointWithAltitude(c)); });
    return fence;
}

Json geoFenceJson(const RouteFence &fence)
{
    Json polygons = Json::array(), circles = Json::array();
    for (const FencePolygon &p : fence.polygons) {
        Json ring = Json::array();
        for (const GeoPoint &g : p.vertices)
            ring.push_back({g.latitude, g.longitude});
        polygons.push_back({{"inclusion", p.inclusion}, {"polygon", std::move(ring)}, {"version", 1}});
    }
    for (const FenceCircle &c : fence.circles)
        circles.push_back({{"circle", {{"center", {c.center.latitude, c.center.longitude}}, {"radius", c.radius}}},
                           {"inclusion", c.inclusion}, {"version", 1}});
    Json out{{"circles", std::move(circles)}, {"polygons", std::move(polygons)}, {"version", 2}};
    if (fence.breachReturn)
        out["breachReturn"] = {fence.breachReturn->position.latitude, fence.breachReturn->position.longitude, fence.breachReturn->altitude};
    return out;
}

Json rallyPointsJson(const RouteFence &fence)
{
    Json points = Json::array();
    for (const FencePoint &p : fence.rallyPoints)
        points.push_back({p.position.latitude, p.position.longitude, p.altitude});
    return Json{{"points", std::move(points)}, {"version", 2}};
}

} // namespace sortie::mission::formats
