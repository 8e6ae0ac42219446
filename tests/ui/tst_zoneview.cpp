// Zones where the operator plans, offscreen with the program's own wiring against sortie-sim: a
// zone drawn with the mouse across the open route is hatched on the map, its error is in the
// validation list (a click chooses the leg and the zone), the terrain profile shows its limits where
// the route crosses it, and Upload is refused naming it; the drawn zone's corner dragged on the map
// is one undo step. And the zone layer's own drawing: hatch where a zone is, green where an inclusion
// zone's edge is, labels that never overlap, a tooltip with source and limits.
#include "Airspace.h"
#include "MapPalette.h"
#include "ClientWindow.h"
#include "FleetRoutes.h"
#include "LabelPlacer.h"
#include "MapView.h"
#include "MissionUploader.h"
#include "QuickScene.h"
#include "RouteAnalyzer.h"
#include "RouteDocument.h"
#include "RouteLayer.h"
#include "RouteModel.h"
#include "RoutePreparation.h"
#include "VehicleLayer.h"
#include "ZoneCrossingLayer.h"
#include "ZoneEditor.h"
#include "ZoneLayer.h"
#include "ZoneProfileOverlay.h"

#include <QDir>
#include <QSettings>
#include <QStandardItemModel>
#include <QSignalSpy>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

mission::Route lineRoute(const QGeoCoordinate &origin)
{
    mission::Route route;
    route.settings.name = QStringLiteral("Through the works");
    for (int i = 0; i <= 4; ++i) {
        const QGeoCoordinate p = origin.atDistanceAndAzimuth(100.0 * i, 90);
        mission::Waypoint w;
        w.position = {p.latitude(), p.longitude()};
        w.altitude = 25;
        w.speed = 6;
        route.segments.push_back(w);
    }
    return route;
}

QPointF centreOf(QQuickItem *item)
{
    return item->mapToScene(QPointF(item->width() / 2, item->height() / 2));
}

void click(QQuickWindow *window, QPointF at)
{
    QTest::mouseClick(window, Qt::LeftButton, {}, at.toPoint());
}

// Pixels near `at` within `radius` that are `colour` (within 40 a channel).
int countNear(const QImage &image, QPointF at, int radius, const QColor &colour)
{
    int n = 0;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const QPoint p = (at + QPointF(dx, dy)).toPoint();
            n += image.rect().contains(p) && test::colourDistance(image.pixel(p), colour.rgb()) < 40;
        }
    return n;
}

QString screenshotDir()
{
    return qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR));
}

const QByteArray kLayerScene = R"(
import QtQuick
import Sortie.Ui
Item {
    required property Airspace airspace
    MapView { id: map; objectName: "map"; anchors.fill: parent; latitude: 56.95; longitude: 24.1; zoomLevel: 14 }
    ZoneLayer { objectName: "zones"; anchors.fill: parent; map: map; airspace: parent.airspace }
}
)";

// The zone layer under a vehicle layer whose labels keep clear of the zones' (as both pages have them).
const QByteArray kLabelsScene = R"(
import QtQuick
import Sortie.Ui
Item {
    required property Airspace airspace
    required property var vehicles
    MapView { id: map; objectName: "map"; anchors.fill: parent; latitude: 56.95; longitude: 24.1; zoomLevel: 14 }
    ZoneLayer { id: zones; objectName: "zones"; anchors.fill: parent; map: map; airspace: parent.airspace }
    VehicleLayer { objectName: "vehicles"; anchors.fill: parent; map: map; model: parent.vehicles; labelsBelow: zones }
}
)";

} // namespace

class TestZoneView : public QObject
{
    Q_OBJECT

    vehicle::Vehicle *emu101(test::ClientWindow &client) const
    {
        for (int r = 0; r < client.fleet().count(); ++r)
            if (client.fleet().vehicleAt(r)->name() == QStringLiteral("EMU-101"))
                return client.fleet().vehicleAt(r);
        return nullptr;
    }

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void aZoneDrawnAcrossTheRouteRefusesItsUpload()
    {
        test::ClientWindow client;
        QVERIFY2(client.isReady(), qPrintable(client.error()));
        QVERIFY(client.logIn());
        QTRY_VERIFY_WITH_TIMEOUT(emu101(client), 10000);
        vehicle::Vehicle *emu = emu101(client);
        client.showPage(1);
        client::RouteDocument *doc = client.missions().document();
        const QGeoCoordinate origin = emu->position().isValid() ? emu->position() : QGeoCoordinate(56.95, 24.1);
        doc->load(lineRoute(origin));
        auto *routeLayer = client.find<ui::RouteLayer>(QStringLiteral("routeLayer"));
        QTRY_COMPARE(routeLayer->count(), 5);
        auto *map = client.page("missionPage")->property("map").value<ui::MapView *>();
        const QGeoCoordinate east = origin.atDistanceAndAzimuth(400, 90);
        QCOMPARE(doc->analyzer()->validation().errorCount(), 0);
        // The route is for EMU-101, picked as the operator picks it; the fleet's route list opens
        // beside the map with it, so the map's layout settles before anything is drawn on it.
        int emuRow = -1;
        for (int r = 0; r < client.fleet().count(); ++r)
            if (client.fleet().vehicleAt(r) == emu)
                emuRow = r;
        client.find<QObject>(QStringLiteral("vehiclePicker"))->setProperty("currentIndex", emuRow);
        QTRY_VERIFY(client.graph().fleetRoutes()->count() > 0);

        // The zone panel, the polygon tool, four corners around leg 4 (300–400 m), Create.
        airspace::Airspace &airspace = client.graph().airspace();
        click(client.window(), centreOf(client.find(QStringLiteral("zonesButton"))));
        QQuickItem *panel = client.find(QStringLiteral("zonePanel"));
        QTRY_VERIFY(panel->isVisible());
        // The zone's place in the map's right part (the zone panel is over its left), once the page's
        // layout has settled (the fleet's route list may have opened beside the map).
        QTest::qWait(300);
        map->fitBounds(origin.latitude() - 0.0015, origin.longitude() - 0.001, origin.latitude() + 0.0015, east.longitude() + 0.001, 60);
        QTest::qWait(100);
        const double zoneX = map->mapToScene(map->fromCoordinate(origin.atDistanceAndAzimuth(330, 90))).x();
        const double panelRight = panel->mapToScene(QPointF(panel->width(), 0)).x();
        QVERIFY2(zoneX > panelRight + 20, qPrintable(QStringLiteral("zone at x %1, panel to %2, map %3 wide at %4")
                                                        .arg(zoneX).arg(panelRight).arg(map->width()).arg(map->mapToScene(QPointF(0, 0)).x())));
        click(client.window(), centreOf(client.find(QStringLiteral("drawZonePolygon"))));
        const auto onMap = [map](const QGeoCoordinate &c) { return map->mapToScene(map->fromCoordinate(c)); };
        const QGeoCoordinate a = origin.atDistanceAndAzimuth(330, 90), b = origin.atDistanceAndAzimuth(370, 90);
        const QGeoCoordinate corners[] = {a.atDistanceAndAzimuth(40, 180), b.atDistanceAndAzimuth(40, 180), b.atDistanceAndAzimuth(40, 0),
                                          a.atDistanceAndAzimuth(40, 0)};
        for (const QGeoCoordinate &c : corners)
            click(client.window(), onMap(c));
        QQuickItem *create = client.find(QStringLiteral("finishZoneButton"));
        QTRY_VERIFY(create->isVisible() && create->isEnabled());
        click(client.window(), centreOf(create));
        // The drawn zone is row 0; the server's zones around the demo follow it in the store.
        QTRY_VERIFY2(airspace.customZones().size() == 1, qPrintable(client.find<QObject>(QStringLiteral("zoneRefusal"))->property("text").toString()));
        QCOMPARE(doc->model()->rowCount(), 5); // the clicks drew the zone, not waypoints
        QCOMPARE(airspace.editor()->undoStack()->count(), 1);

        // Its fields as they are: no floor and no ceiling are empty fields ("ground", "unlimited"),
        // never "0"; limits set show as typed, in their reference. Undone, so the steps below count
        // as before.
        QQuickItem *floorField = client.find(QStringLiteral("zoneFloor"));
        QQuickItem *ceilingField = client.find(QStringLiteral("zoneCeiling"));
        QTRY_VERIFY(floorField->isVisible());
        QCOMPARE(client.find(QStringLiteral("zoneName"))->property("text").toString(), QStringLiteral("Zone 1"));
        QCOMPARE(floorField->property("text").toString(), QString());
        QCOMPARE(ceilingField->property("text").toString(), QString());
        QCOMPARE(client.find(QStringLiteral("zoneKind"))->property("currentIndex").toInt(), 0);
        QVERIFY(airspace.editor()->setLimits(0, 30, 120.5, QStringLiteral("AGL")));
        QTRY_COMPARE(floorField->property("text").toString(), QStringLiteral("30"));
        QCOMPARE(ceilingField->property("text").toString(), QStringLiteral("120.5"));
        QCOMPARE(client.find(QStringLiteral("zoneReference"))->property("currentText").toString(), QStringLiteral("AGL"));
        airspace.editor()->undo();
        QTRY_COMPARE(floorField->property("text").toString(), QString());

        // The error, listed, naming the zone and where along the route.
        QTRY_VERIFY_WITH_TIMEOUT(doc->analyzer()->validation().errorCount() > 0, 5000);
        QQuickItem *issues = client.find(QStringLiteral("validationList"));
        QTRY_VERIFY(issues->isVisible());
        // The list's rows are made anew whenever the analyzer runs again (the server's terrain
        // answering): the row is found afresh for each try.
        const auto issueRow = [issues]() -> QQuickItem * {
            for (QQuickItem *child : issues->property("contentItem").value<QQuickItem *>()->childItems())
                if (child->property("message").toString().contains(QStringLiteral("'Zone 1'")))
                    return child;
            return nullptr;
        };
        QTRY_VERIFY(issueRow());
        QVERIFY2(issueRow()->property("message").toString().startsWith(QStringLiteral("Leg 4 enters 'Zone 1' from 3")),
                 qPrintable(issueRow()->property("message").toString()));
        // A click on it chooses the leg (the row it ends at) and the zone.
        airspace.setSelectedZone(-1);
        QTRY_VERIFY_WITH_TIMEOUT(([&] {
            if (QQuickItem *row = issueRow())
                click(client.window(), centreOf(row));
            return airspace.selectedZone() == 0;
        })(), 10000);
        QCOMPARE(doc->selectedRows(), QList<int>{4});

        // The terrain profile marks where the route is inside it.
        auto *profile = client.find<ui::ZoneProfileOverlay>(QStringLiteral("zoneProfile"));
        QVERIFY(profile);
        QCOMPARE(profile->airspace(), &airspace);
        QTRY_COMPARE(airspace.crossingCount(), 1);
        QTRY_COMPARE(profile->bandCount(), 1);

        // On the map: the stretch of leg 4 inside the zone red over the route.
        auto *stretches = client.find<ui::ZoneCrossingLayer>(QStringLiteral("zoneCrossingLayer"));
        QTRY_COMPARE(stretches->stretchCount(), 1);
        const QPointF middle = stretches->mapToScene(stretches->stretchMiddle(0));
        const QPointF expected = onMap(origin.atDistanceAndAzimuth(350, 90));
        QVERIFY2(QLineF(middle, expected).length() < 4, qPrintable(QStringLiteral("%1,%2 vs %3,%4").arg(middle.x()).arg(middle.y()).arg(expected.x()).arg(expected.y())));

        // On the map: hatched red inside the zone, its label, its tooltip.
        auto *zones = client.find<ui::ZoneLayer>(QStringLiteral("missionZoneLayer"));
        const auto drawnZoneLabelled = [zones] {
            for (int i = 0; i < zones->labelCount(); ++i)
                if (zones->labelZone(i) == 0)
                    return true;
            return false;
        };
        QTRY_VERIFY(drawnZoneLabelled());
        QVERIFY(test::waitForFrame(client.window()));
        const QImage image = client.window()->grabWindow();
        image.save(QDir(screenshotDir()).filePath(QStringLiteral("zones.png")));
        const QPointF inside = onMap(origin.atDistanceAndAzimuth(350, 90).atDistanceAndAzimuth(25, 180));
        QVERIFY2(countNear(image, inside, 10, ui::MapPalette::light().exclusion) > 4, "no red hatch inside the zone");
        // The leg red where it is inside (its line's own pixels, which the route draws over the hatch),
        // and not where it is not.
        QVERIFY2(countNear(image, onMap(origin.atDistanceAndAzimuth(340, 90)), 1, ui::MapPalette::light().crossing) >= 5, "the leg is not red in the zone");
        QCOMPARE(countNear(image, onMap(origin.atDistanceAndAzimuth(260, 90)), 1, ui::MapPalette::light().crossing), 0);
        QCOMPARE(profile->bandCount(), 1);
        const QRectF band = profile->bandRect(0);
        QVERIFY2(countNear(image, profile->mapToScene(band.center()), 6, ui::MapPalette::light().exclusion) > 2, "no red band on the profile");

        // Hovered: the tooltip says where it comes from and its limits.
        zones->hoverAt(zones->mapFromScene(onMap(origin.atDistanceAndAzimuth(350, 90).atDistanceAndAzimuth(30, 0))));
        QVERIFY2(zones->hoverText().contains(QStringLiteral("Zone 1")) && zones->hoverText().contains(QStringLiteral("ground"))
                     && zones->hoverText().contains(QStringLiteral("drawn")),
                 qPrintable(zones->hoverText()));
        zones->hoverAt(QPointF(-10, -10)); // the mouse leaves: the tooltip closes
        QVERIFY(zones->hoverText().isEmpty());
        // Upload: refused, naming the zone; nothing reaches the vehicle.
        client::RoutePreparation *preparation = client.missions().preparation();
        client::MissionUploader *uploader = preparation->uploader();
        QSignalSpy finished(uploader, &client::MissionUploader::finished);
        QQuickItem *upload = client.find(QStringLiteral("uploadButton"));
        QTRY_VERIFY(upload->isVisible() && upload->isEnabled());
        click(client.window(), centreOf(upload));
        QTRY_VERIFY_WITH_TIMEOUT(!finished.isEmpty(), 15000);
        QVERIFY(uploader->state() != client::MissionUploader::State::Done);
        const QString message = client.find<QObject>(QStringLiteral("preparationMessage"))->property("text").toString();
        QVERIFY2(message.contains(QStringLiteral("Zone 1")), qPrintable(message));
        QVERIFY(emu->mission().empty());

        // The zone's corner dragged on the map: one undo step; Ctrl+Z (the zone panel open) takes it back.
        const QGeoCoordinate corner = corners[1];
        const QGeoCoordinate farther = corner.atDistanceAndAzimuth(30, 90);
        QTest::mousePress(client.window(), Qt::LeftButton, {}, onMap(corner).toPoint());
        for (int i = 1; i <= 5; ++i)
            QTest::mouseMove(client.window(), (onMap(corner) + (onMap(farther) - onMap(corner)) * i / 5).toPoint());
        QTest::mouseRelease(client.window(), Qt::LeftButton, {}, onMap(farther).toPoint());
        QTRY_COMPARE(airspace.editor()->undoStack()->count(), 2);
        const auto cornerNow = [&airspace] { return std::get<airspace::ZonePolygons>(airspace.zoneAt(0).shape).parts[0].rings[0][1]; };
        QVERIFY2(std::abs(cornerNow().longitude - farther.longitude()) < 2e-5, qPrintable(QString::number(cornerNow().longitude - farther.longitude())));
        QCOMPARE(doc->undoStack()->count(), 0); // the route is not touched
        QMetaObject::invokeMethod(client.window(), "undo");
        QVERIFY(std::abs(cornerNow().longitude - corner.longitude()) < 2e-5);

        // Sent to the server from the zone panel: listed once, as the server's, and still chosen.
        QQuickItem *send = client.find(QStringLiteral("sendZoneButton"));
        QTRY_VERIFY(send->isVisible() && send->isEnabled());
        QCOMPARE(send->property("text").toString(), QStringLiteral("Send to server"));
        click(client.window(), centreOf(send));
        QTRY_VERIFY_WITH_TIMEOUT(airspace.customZones().empty(), 10000);
        const auto rowsNamed = [&airspace](const QString &name) {
            QList<int> rows;
            for (int r = 0; r < airspace.count(); ++r)
                if (airspace.zoneAt(r).name == name)
                    rows << r;
            return rows;
        };
        QTRY_COMPARE_WITH_TIMEOUT(rowsNamed(QStringLiteral("Zone 1")).size(), 1, 10000);
        const int stored = rowsNamed(QStringLiteral("Zone 1")).first();
        QCOMPARE(airspace.groupOf(stored), airspace::Airspace::Group::Server);
        QTRY_COMPARE(airspace.selectedZone(), stored);
        QCOMPARE(client.find<QObject>(QStringLiteral("zoneSharingStatus"))->property("text").toString(),
                 QStringLiteral("Zone 'Zone 1' is on the server."));
        // The server's zone edited here: a drawn copy, sent back as an update; discarded, the
        // server's comes back; deleted after the question, it is gone.
        QQuickItem *editHere = client.find(QStringLiteral("editServerZone"));
        QTRY_VERIFY(editHere->isVisible());
        QVERIFY(test::waitForFrame(client.window()));
        client.window()->grabWindow().save(QDir(screenshotDir()).filePath(QStringLiteral("zone-sharing.png")));
        click(client.window(), centreOf(editHere));
        QTRY_COMPARE(airspace.customZones().size(), size_t(1));
        QVERIFY(airspace.customZones()[0].serverId);
        QTRY_COMPARE(send->property("text").toString(), QStringLiteral("Update on server"));
        QCOMPARE(rowsNamed(QStringLiteral("Zone 1")), QList<int>{0});
        QQuickItem *discard = client.find(QStringLiteral("removeZoneButton"));
        QCOMPARE(discard->property("text").toString(), QStringLiteral("Discard copy"));
        click(client.window(), centreOf(discard));
        QTRY_VERIFY(airspace.customZones().empty());
        QCOMPARE(rowsNamed(QStringLiteral("Zone 1")).size(), 1);
        airspace.setSelectedZone(rowsNamed(QStringLiteral("Zone 1")).first());
        QQuickItem *deleteButton = client.find(QStringLiteral("deleteServerZone"));
        QTRY_VERIFY(deleteButton->isVisible() && deleteButton->isEnabled());
        click(client.window(), centreOf(deleteButton));
        QObject *question = client.find<QObject>(QStringLiteral("deleteZoneQuestion"));
        QTRY_VERIFY(question->property("opened").toBool());
        QMetaObject::invokeMethod(question, "accept");
        QTRY_VERIFY_WITH_TIMEOUT(rowsNamed(QStringLiteral("Zone 1")).isEmpty(), 10000);

        // The fly view draws the zone too.
        client.showPage(2);
        auto *flyZones = client.find<ui::ZoneLayer>(QStringLiteral("flyZoneLayer"));
        QVERIFY(flyZones);
        QCOMPARE(flyZones->airspace(), &airspace);
    }

    // A vehicle whose label would sit on a zone's: the vehicle's gives way (the moving label, so
    // the zones are not drawn again as it moves); without labelsBelow the two would overlap.
    void vehicleLabelsGiveWayToZoneLabels()
    {
        QTemporaryDir dir;
        QSettings settings(dir.filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
        mission::RouteModel route;
        mission::RouteAnalyzer analyzer(&route);
        airspace::Airspace store(&settings, &analyzer, &route, nullptr);
        store.editor()->addCircle(QGeoCoordinate(56.95, 24.1), 150);
        QStandardItemModel vehicles;
        vehicles.setItemRoleNames({{Qt::UserRole + 1, "vehicleId"}, {Qt::UserRole + 2, "name"}, {Qt::UserRole + 3, "latitude"},
                                   {Qt::UserRole + 4, "longitude"}, {Qt::UserRole + 5, "heading"}});
        test::QuickScene scene(kLabelsScene, QSize(800, 600),
                               {{QStringLiteral("airspace"), QVariant::fromValue<QObject *>(&store)},
                                {QStringLiteral("vehicles"), QVariant::fromValue<QObject *>(&vehicles)}});
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *zones = scene.find<ui::ZoneLayer>(QStringLiteral("zones"));
        auto *layer = scene.find<ui::VehicleLayer>(QStringLiteral("vehicles"));
        auto *map = scene.find<ui::MapView>(QStringLiteral("map"));
        QTRY_COMPARE(zones->labelCount(), 1);
        const QRectF zoneLabel = zones->labelRect(0);
        // Where the vehicle's label would start on the zone label's left half, its mark just left of it.
        const QPointF mark = zoneLabel.topLeft() + QPointF(8, zoneLabel.height() / 2) - ui::LabelPlacer::kOffset;
        const QGeoCoordinate at = map->toCoordinate(map->mapFromItem(layer, mark));
        auto *item = new QStandardItem;
        item->setData(QStringLiteral("v1"), Qt::UserRole + 1);
        item->setData(QStringLiteral("EMU-101 with a long name"), Qt::UserRole + 2);
        item->setData(at.latitude(), Qt::UserRole + 3);
        item->setData(at.longitude(), Qt::UserRole + 4);
        item->setData(90.0, Qt::UserRole + 5);
        vehicles.appendRow(item);
        QTRY_VERIFY(!layer->labelRect(0).isEmpty());
        scene.grab();
        QVERIFY2(!layer->labelRect(0).intersects(zones->labelRect(0)),
                 qPrintable(QStringLiteral("vehicle label %1,%2 %3x%4 on the zone's %5,%6 %7x%8")
                                .arg(layer->labelRect(0).x()).arg(layer->labelRect(0).y()).arg(layer->labelRect(0).width()).arg(layer->labelRect(0).height())
                                .arg(zoneLabel.x()).arg(zoneLabel.y()).arg(zoneLabel.width()).arg(zoneLabel.height())));
        scene.grab().save(QDir(screenshotDir()).filePath(QStringLiteral("zone-vehicle-labels.png")));
        // The control: without the zones' labels to keep clear of, it lands on them.
        layer->setLabelsBelow(nullptr);
        QTRY_VERIFY(layer->labelRect(0).intersects(zones->labelRect(0)));
    }

    void theLayerHatchesOutlinesAndLabelsWithoutOverlap()
    {
        QTemporaryDir dir;
        QSettings settings(dir.filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
        mission::RouteModel route;
        mission::RouteAnalyzer analyzer(&route);
        airspace::Airspace store(&settings, &analyzer, &route, nullptr);
        // Four zones whose middles are close together (their labels would collide), and an inclusion zone.
        const QGeoCoordinate centre(56.95, 24.1);
        for (int i = 0; i < 4; ++i)
            store.editor()->addCircle(centre.atDistanceAndAzimuth(40.0 * i, 45), 150 + 20 * i);
        const QGeoCoordinate west = centre.atDistanceAndAzimuth(900, 270);
        store.editor()->addPolygon({west.atDistanceAndAzimuth(200, 45), west.atDistanceAndAzimuth(200, 135), west.atDistanceAndAzimuth(200, 225),
                                    west.atDistanceAndAzimuth(200, 315)});
        QVERIFY(store.editor()->setKind(4, QStringLiteral("inclusion")));
        QVERIFY(store.editor()->setLimits(4, QStringLiteral("20"), QStringLiteral("120"), QStringLiteral("AGL")));

        test::QuickScene scene(kLayerScene, QSize(800, 600), {{QStringLiteral("airspace"), QVariant::fromValue<QObject *>(&store)}});
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *layer = scene.find<ui::ZoneLayer>(QStringLiteral("zones"));
        QVERIFY(layer);
        QTRY_VERIFY(layer->labelCount() >= 2);
        const QImage image = scene.grab();
        image.save(QDir(screenshotDir()).filePath(QStringLiteral("zone-layer.png")));

        // Hatched red where an exclusion zone is (off its label), green on the inclusion zone's edge.
        const QPointF south = layer->mapToScene(scene.find<ui::MapView>(QStringLiteral("map"))->fromCoordinate(centre.atDistanceAndAzimuth(100, 200)));
        QVERIFY2(countNear(image, south, 8, ui::MapPalette::light().exclusion) > 4, "no hatch in the zone");
        const QPointF edge = layer->mapToScene(scene.find<ui::MapView>(QStringLiteral("map"))->fromCoordinate(west.atDistanceAndAzimuth(141, 180)));
        QVERIFY2(countNear(image, edge, 4, ui::MapPalette::light().inclusion) > 2, "no green outline on the inclusion zone's edge");
        // Nothing red in the inclusion zone's middle (outlined, not hatched), away from its label.
        const QPointF westInside = layer->mapToScene(scene.find<ui::MapView>(QStringLiteral("map"))->fromCoordinate(west.atDistanceAndAzimuth(80, 200)));
        QCOMPARE(countNear(image, westInside, 6, ui::MapPalette::light().exclusion), 0);

        // No two labels overlap; the inclusion zone's says its limits.
        for (int i = 0; i < layer->labelCount(); ++i)
            for (int j = i + 1; j < layer->labelCount(); ++j)
                QVERIFY2(!layer->labelRect(i).intersects(layer->labelRect(j)), qPrintable(QStringLiteral("labels %1 and %2").arg(i).arg(j)));
        bool inclusionLabelled = false;
        for (int i = 0; i < layer->labelCount(); ++i)
            inclusionLabelled |= layer->labelZone(i) == 4;
        QVERIFY(inclusionLabelled);
        const QString tip = layer->describe(4);
        QVERIFY2(tip.contains(QStringLiteral("inclusion")) && tip.contains(QStringLiteral("20 m AGL")) && tip.contains(QStringLiteral("120 m AGL"))
                     && tip.contains(QStringLiteral("drawn")),
                 qPrintable(tip));
        // The mouse over the zone: the map still shows where the cursor is, and the tooltip says
        // what the zone is; off every zone, nothing.
        auto *map = scene.find<ui::MapView>(QStringLiteral("map"));
        QTest::mouseMove(&scene.view(), westInside.toPoint());
        QTRY_VERIFY(map->isCursorInside());
        QTRY_COMPARE(layer->hoverText(), tip);
        QTest::mouseMove(&scene.view(), QPoint(790, 590));
        QTRY_VERIFY(layer->hoverText().isEmpty());
        QVERIFY(map->isCursorInside());

        // Switched off: grey dashes, no hatch.
        store.setActive(0, false);
        store.setActive(1, false);
        store.setActive(2, false);
        store.setActive(3, false);
        QTest::qWait(50);
        const QImage off = scene.grab();
        QCOMPARE(countNear(off, south, 8, ui::MapPalette::light().exclusion), 0);
    }
};

QTEST_MAIN(TestZoneView)
#include "tst_zoneview.moc"
