// The zone readers: GeoJSON, KML and a .plan's geofence, good files and bad ones (a bad feature is
// named and left out, the rest kept), and the .plan geofence and rally points both ways.
#include "MissionFiles.h"
#include "QgcPlanFormat.h"
#include "ZoneFiles.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace sortie::airspace;
using namespace sortie::mission;

namespace {
const QByteArray kGeoJson = R"({"type": "FeatureCollection", "features": [
  {"type": "Feature", "properties": {"name": "RIX CTR", "kind": "exclusion", "floor": 0, "ceiling": 150, "reference": "AMSL"},
   "geometry": {"type": "Polygon", "coordinates": [[[24.0, 56.9], [24.1, 56.9], [24.1, 57.0], [24.0, 57.0], [24.0, 56.9]],
                                                   [[24.04, 56.94], [24.06, 56.94], [24.06, 56.96], [24.04, 56.94]]]}},
  {"type": "Feature", "properties": {"name": "Two fields", "kind": "inclusion"},
   "geometry": {"type": "MultiPolygon", "coordinates": [[[[24.2, 56.9], [24.3, 56.9], [24.3, 57.0], [24.2, 56.9]]],
                                                        [[[24.4, 56.9], [24.5, 56.9], [24.5, 57.0], [24.4, 56.9]]]]}},
  {"type": "Feature", "properties": {"name": "Mast", "radius": 250, "ceiling": 90, "reference": "AGL"},
   "geometry": {"type": "Point", "coordinates": [24.15, 56.95]}},
  {"type": "Feature", "properties": {"name": "Funnel", "radius": 100, "topRadius": 900, "floor": 0, "ceiling": 300, "active": false},
   "geometry": {"type": "Point", "coordinates": [24.16, 56.96, 12]}}
]})";
} // namespace

class TstAirspaceFiles : public QObject
{
    Q_OBJECT
private slots:
    void geoJsonZones()
    {
        const Result<ZoneFile> read = readGeoJsonZones(kGeoJson, QStringLiteral("zones.geojson"));
        QVERIFY2(read.ok(), read.ok() ? "" : qPrintable(read.error().toString()));
        QVERIFY2(read->problems.isEmpty(), qPrintable(read->problems.join('\n')));
        QCOMPARE(read->zones.size(), size_t(4));
        const Zone &ctr = read->zones[0];
        QCOMPARE(ctr.name, QStringLiteral("RIX CTR"));
        QCOMPARE(ctr.kind, ZoneKind::Exclusion);
        QVERIFY(ctr.floor && ctr.floor->metres == 0 && ctr.ceiling && ctr.ceiling->metres == 150);
        QCOMPARE(ctr.ceiling->reference, HeightReference::Amsl);
        const auto &rings = std::get<ZonePolygons>(ctr.shape).parts.front().rings;
        QCOMPARE(rings.size(), size_t(2));
        QCOMPARE(rings[0].size(), size_t(4));  // the closing position dropped
        QCOMPARE(rings[0][1], (GeoPoint{56.9, 24.1}));  // [longitude, latitude]
        QCOMPARE(ctr.origin, QStringLiteral("zones.geojson, RIX CTR"));

        const Zone &fields = read->zones[1];
        QCOMPARE(fields.kind, ZoneKind::Inclusion);
        QCOMPARE(std::get<ZonePolygons>(fields.shape).parts.size(), size_t(2));
        QVERIFY(!fields.floor && !fields.ceiling);  // the ground, unlimited

        const Zone &mast = read->zones[2];
        QCOMPARE(std::get<ZoneCircle>(mast.shape).radius, 250.0);
        QCOMPARE(mast.ceiling->reference, HeightReference::AboveTerrain);
        QVERIFY(!mast.floor);

        const Zone &funnel = read->zones[3];
        const auto &cone = std::get<ZoneConeFrustum>(funnel.shape);
        QCOMPARE(cone.bottomRadius, 100.0);
        QCOMPARE(cone.topRadius, 900.0);
        QVERIFY(!funnel.active);
    }

    // Published files repeat a vertex; a ring of three distinct positions written with four is a
    // triangle, not a four-cornered zone with a zero-length edge (the same ring reader as ED-318's).
    void geoJsonRepeatedVerticesAreOne()
    {
        const QByteArray json = R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"name": "T"},
          "geometry": {"type": "Polygon", "coordinates": [[[24.0, 56.9], [24.1, 56.9], [24.1, 56.9], [24.1, 57.0], [24.0, 56.9]]]}}]})";
        const Result<ZoneFile> read = readGeoJsonZones(json, QStringLiteral("t.geojson"));
        QVERIFY2(read.ok(), read.ok() ? "" : qPrintable(read.error().toString()));
        QCOMPARE(read->zones.size(), size_t(1));
        const auto &ring = std::get<ZonePolygons>(read->zones[0].shape).parts.front().rings.front();
        QCOMPARE(ring.size(), size_t(3));
        QCOMPARE(ring[2], (GeoPoint{57.0, 24.1}));
    }

    void badGeoJsonFeaturesAreNamed_data()
    {
        QTest::addColumn<QByteArray>("feature");
        QTest::addColumn<QString>("words");
        QTest::newRow("kind") << QByteArray(R"({"type": "Feature", "properties": {"name": "Bad", "kind": "forbidden"},
            "geometry": {"type": "Point", "coordinates": [24, 56]}})") << "feature 2 ('Bad') (at /features/1/properties/kind) was left out: kind \"forbidden\"";
        QTest::newRow("ceiling under floor") << QByteArray(R"({"type": "Feature", "properties": {"name": "Low", "floor": 100, "ceiling": 50},
            "geometry": {"type": "Point", "coordinates": [24, 56]}})") << "the ceiling (50 m) is not above the floor (100 m)";
        QTest::newRow("no radius") << QByteArray(R"({"type": "Feature", "properties": {"name": "Dot"},
            "geometry": {"type": "Point", "coordinates": [24, 56]}})") << "needs properties.radius";
        QTest::newRow("line") << QByteArray(R"({"type": "Feature", "properties": {},
            "geometry": {"type": "LineString", "coordinates": [[24, 56], [25, 57]]}})") << "feature 2 (at /features/1/geometry/type) was left out: geometry LineString";
        QTest::newRow("latitude") << QByteArray(R"({"type": "Feature", "properties": {"name": "Far"},
            "geometry": {"type": "Polygon", "coordinates": [[[24, 96], [25, 56], [25, 57]]]}})") << "/features/1/geometry/coordinates/0/0";
        QTest::newRow("two points") << QByteArray(R"({"type": "Feature", "properties": {"name": "Thin"},
            "geometry": {"type": "Polygon", "coordinates": [[[24, 56], [25, 56], [24, 56]]]}})") << "at least 3 distinct positions";
        QTest::newRow("bow tie") << QByteArray(R"({"type": "Feature", "properties": {"name": "Bow"},
            "geometry": {"type": "Polygon", "coordinates": [[[24, 56], [25, 57], [25, 56], [24, 57]]]}})") << "feature 2 ('Bow') (at /features/1/geometry/coordinates) was left out: the polygon cannot be checked";
        QTest::newRow("reference") << QByteArray(R"({"type": "Feature", "properties": {"name": "Ref", "reference": "FL"},
            "geometry": {"type": "Polygon", "coordinates": [[[24, 56], [25, 56], [25, 57]]]}})") << "reference \"FL\"";
    }

    // The good feature before the bad one and the one after are kept.
    void badGeoJsonFeaturesAreNamed()
    {
        QFETCH(QByteArray, feature);
        QFETCH(QString, words);
        const QByteArray good = R"({"type": "Feature", "properties": {"name": "Good"},
            "geometry": {"type": "Polygon", "coordinates": [[[24, 56], [25, 56], [25, 57]]]}})";
        const Result<ZoneFile> read = readGeoJsonZones("{\"type\": \"FeatureCollection\", \"features\": [" + good + "," + feature + "," + good + "]}");
        QVERIFY(read.ok());
        QCOMPARE(read->zones.size(), size_t(2));
        QCOMPARE(read->problems.size(), 1);
        QVERIFY2(read->problems.front().contains(words), qPrintable(read->problems.front()));
    }

    void notGeoJsonIsAnError()
    {
        const Result<ZoneFile> syntax = readGeoJsonZones("{\"type\": \"FeatureCollection\",\n \"features\": [}");
        QVERIFY(!syntax.ok());
        QCOMPARE(syntax.error().line, 2);
        const Result<ZoneFile> other = readGeoJsonZones(R"({"type": "Topology"})");
        QVERIFY(!other.ok());
        QVERIFY(other.error().toString().contains(QStringLiteral("not a GeoJSON FeatureCollection")));
    }

    void kmlZones()
    {
        const QByteArray kml = R"(<?xml version="1.0" encoding="UTF-8"?>
<kml><Document>
  <Placemark><name>Prison</name><Polygon><outerBoundaryIs><LinearRing><coordinates>
    24.0,56.9,0 24.1,56.9,0 24.1,57.0,0 24.0,56.9,0
  </coordinates></LinearRing></outerBoundaryIs>
  <innerBoundaryIs><LinearRing><coordinates>24.05,56.92 24.06,56.92 24.06,56.93</coordinates></LinearRing></innerBoundaryIs></Polygon></Placemark>
  <Placemark><name>Broken</name><Polygon><outerBoundaryIs><LinearRing><coordinates>
    24.0,56.9 east,56.9 24.1,57.0
  </coordinates></LinearRing></outerBoundaryIs></Polygon></Placemark>
  <Placemark><name>Just a point</name><Point><coordinates>24.0,56.9</coordinates></Point></Placemark>
  <Placemark><name>Two parks</name><MultiGeometry>
    <Polygon><outerBoundaryIs><LinearRing><coordinates>24.2,56.9 24.3,56.9 24.3,57.0</coordinates></LinearRing></outerBoundaryIs></Polygon>
    <Polygon><outerBoundaryIs><LinearRing><coordinates>24.4,56.9 24.5,56.9 24.5,57.0</coordinates></LinearRing></outerBoundaryIs></Polygon>
  </MultiGeometry></Placemark>
</Document></kml>)";
        const Result<ZoneFile> read = readKmlZones(kml);
        QVERIFY2(read.ok(), read.ok() ? "" : qPrintable(read.error().toString()));
        QCOMPARE(read->zones.size(), size_t(2));
        QCOMPARE(read->zones[0].name, QStringLiteral("Prison"));
        QCOMPARE(read->zones[0].kind, ZoneKind::Exclusion);
        QCOMPARE(std::get<ZonePolygons>(read->zones[0].shape).parts.front().rings.size(), size_t(2));
        QCOMPARE(std::get<ZonePolygons>(read->zones[0].shape).parts.front().rings[0].size(), size_t(3));
        QCOMPARE(read->zones[1].name, QStringLiteral("Two parks"));
        QCOMPARE(std::get<ZonePolygons>(read->zones[1].shape).parts.size(), size_t(2));
        QCOMPARE(read->problems.size(), 1);
        QVERIFY2(read->problems.front().contains(QStringLiteral("Placemark 'Broken' (line 7) was left out: line 7: bad coordinate \"east,56.9\"")),
                 qPrintable(read->problems.front()));

        const Result<ZoneFile> bad = readKmlZones("<kml><Document>\n<Placemark><name>x</Document></kml>");
        QVERIFY(!bad.ok());
        QCOMPARE(bad.error().line, 2);
    }

    void planGeofenceZones()
    {
        const QByteArray plan = R"({"fileType": "Plan", "version": 1, "groundStation": "QGroundControl",
          "geoFence": {"version": 2, "breachReturn": [56.95, 24.1, 40],
            "polygons": [{"inclusion": true, "version": 1, "polygon": [[56.9, 24.0], [56.9, 24.2], [57.0, 24.2], [57.0, 24.0]]},
                         {"inclusion": false, "version": 1, "polygon": [[56.95, 24.05], [56.95, 24.06]]}],
            "circles": [{"inclusion": false, "version": 1, "circle": {"center": [56.96, 24.1], "radius": 120}}]},
          "rallyPoints": {"version": 2, "points": [[56.94, 24.09, 30], [56.97, 24.11, 35]]},
          "mission": {"version": 2, "firmwareType": 12, "vehicleType": 2, "cruiseSpeed": 15, "hoverSpeed": 5,
            "plannedHomePosition": [56.95, 24.1, 10], "items": []}})";
        const Result<ZoneFile> zones = readPlanZones(plan, QStringLiteral("fence.plan"));
        QVERIFY2(zones.ok(), zones.ok() ? "" : qPrintable(zones.error().toString()));
        QCOMPARE(zones->zones.size(), size_t(2));
        QCOMPARE(zones->zones[0].name, QStringLiteral("geofence polygon 1"));
        QCOMPARE(zones->zones[0].kind, ZoneKind::Inclusion);
        QCOMPARE(zones->zones[1].name, QStringLiteral("geofence circle 1"));
        QCOMPARE(zones->zones[1].kind, ZoneKind::Exclusion);
        QCOMPARE(std::get<ZoneCircle>(zones->zones[1].shape).radius, 120.0);
        QCOMPARE(zones->problems.size(), 1);
        QVERIFY2(zones->problems.front().contains(QStringLiteral("/geoFence/polygons/1/polygon")) && zones->problems.front().contains(QStringLiteral("at least 3")),
                 qPrintable(zones->problems.front()));
    }

    // A .plan's geofence and rally points come into the route and go back out as they came; the
    // old "not imported" notices are gone.
    void planFenceRoundTrip()
    {
        const QByteArray plan = R"({"fileType": "Plan", "version": 1, "groundStation": "QGroundControl",
          "geoFence": {"version": 2, "breachReturn": [56.95, 24.1, 40],
            "polygons": [{"inclusion": true, "version": 1, "polygon": [[56.9, 24.0], [56.9, 24.2], [57.0, 24.2], [57.0, 24.0]]},
                         {"inclusion": false, "version": 1, "polygon": [[56.95, 24.05], [56.95, 24.06], [56.96, 24.06]]}],
            "circles": [{"inclusion": true, "version": 1, "circle": {"center": [56.96, 24.1], "radius": 1200}}]},
          "rallyPoints": {"version": 2, "points": [[56.94, 24.09, 30], [56.97, 24.11, 35]]},
          "mission": {"version": 2, "firmwareType": 12, "vehicleType": 2, "cruiseSpeed": 15, "hoverSpeed": 5,
            "plannedHomePosition": [56.95, 24.1, 10], "items": [
              {"type": "SimpleItem", "command": 22, "frame": 3, "autoContinue": true, "doJumpId": 1, "params": [0, 0, 0, null, 56.951, 24.101, 30]},
              {"type": "SimpleItem", "command": 16, "frame": 3, "autoContinue": true, "doJumpId": 2, "params": [0, 0, 0, null, 56.952, 24.102, 30]}]}})";
        const Result<formats::ImportedRoute> read = formats::readQgcPlan(plan);
        QVERIFY2(read.ok(), read.ok() ? "" : qPrintable(read.error().toString()));
        QVERIFY2(!read->notices.join(' ').contains(QStringLiteral("not imported")), qPrintable(read->notices.join('\n')));
        const RouteFence &fence = read->route.fence;
        QCOMPARE(fence.polygons.size(), size_t(2));
        QVERIFY(fence.polygons[0].inclusion && !fence.polygons[1].inclusion);
        QCOMPARE(fence.polygons[1].vertices.size(), size_t(3));
        QCOMPARE(fence.circles.size(), size_t(1));
        QCOMPARE(fence.circles[0].radius, 1200.0);
        QVERIFY(fence.breachReturn && fence.breachReturn->altitude == 40);
        QCOMPARE(fence.rallyPoints.size(), size_t(2));
        QCOMPARE(fence.rallyPoints[1].position, (GeoPoint{56.97, 24.11}));

        const QByteArray written = formats::writeQgcPlan(read->route);
        const Result<formats::ImportedRoute> back = formats::readQgcPlan(written);
        QVERIFY(back.ok());
        QVERIFY(back->route.fence == fence);
        QVERIFY(written.contains("\"breachReturn\""));
        // A route without a fence writes the empty sections QGroundControl expects.
        Route plain = read->route;
        plain.fence = {};
        const QByteArray empty = formats::writeQgcPlan(plain);
        QVERIFY(empty.contains("\"geoFence\"") && empty.contains("\"rallyPoints\"") && !empty.contains("breachReturn"));
        QVERIFY(formats::readQgcPlan(empty)->route.fence.empty());

        // .plan -> .sortie -> .plan keeps them too.
        QTemporaryDir dir;
        Mission m;
        m.routes.push_back(read->route);
        QVERIFY(formats::saveMission(m, dir.filePath(QStringLiteral("fenced.sortie"))).ok());
        const Result<formats::LoadedMission> loaded = formats::loadMission(dir.filePath(QStringLiteral("fenced.sortie")));
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : qPrintable(loaded.error().toString()));
        QVERIFY(loaded->mission.routes.front().fence == fence);
    }

    void zoneFilesByExtension()
    {
        QTemporaryDir dir;
        QFile f(dir.filePath(QStringLiteral("zones.geojson")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(kGeoJson);
        f.close();
        const Result<ZoneFile> read = loadZoneFile(f.fileName());
        QVERIFY(read.ok());
        QCOMPARE(read->zones.size(), size_t(4));
        const Result<ZoneFile> unknown = loadZoneFile(dir.filePath(QStringLiteral("zones.shp")));
        QVERIFY(!unknown.ok());
        QVERIFY(unknown.error().toString().contains(QStringLiteral("zones.shp")));
        QVERIFY(!loadZoneFile(dir.filePath(QStringLiteral("missing.kml"))).ok());
    }
};

QTEST_GUILESS_MAIN(TstAirspaceFiles)
#include "tst_airspacefiles.moc"
