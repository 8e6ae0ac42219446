// The layers' pictures are kept between frames (moved while the map pans, a drag drawn over the
// still route, trails grown piece by piece): these tests check that what is drawn is never stale
// after a pan within and beyond the margin, a zoom, a drag, a colour change or cut trails.
#include "CoordinateListModel.h"
#include "MapView.h"
#include "QuickScene.h"
#include "RouteLayer.h"
#include "VehicleLayer.h"

#include <QItemSelectionModel>
#include <QStandardItemModel>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie::ui;
using sortie::test::colourDistance;
using sortie::test::QuickScene;

namespace {

const QByteArray kScene = R"(
import QtQuick
import Sortie.Ui
Item {
    MapView { id: map; objectName: "map"; anchors.fill: parent; latitude: 56.95; longitude: 24.1; zoomLevel: 14 }
    RouteLayer { objectName: "route"; anchors.fill: parent; map: map; editable: true }
    VehicleLayer { objectName: "vehicles"; anchors.fill: parent; map: map }
}
)";

const QList<QPointF> kWaypoints{{150, 150}, {300, 200}, {450, 150}, {600, 250}};
const QColor kLeg(0x1e, 0x88, 0xe5);
const QColor kMarker = kLeg.darker(130);
const QColor kSelected(0xff, 0x8f, 0x00);
const QColor kFirstVehicle(0xd8, 0x1b, 0x60);

enum VehicleRole { IdRole = Qt::UserRole + 1, NameRole, LatRole, LonRole, StaleRole };

bool near(const QImage &image, QPointF at, const QColor &colour)
{
    return colourDistance(image.pixel(at.toPoint()), colour.rgb()) < 40;
}

// A trail pixel: the vehicle's colour at 170/255 over what the map shows there.
QRgb overMap(const QColor &colour, QRgb map)
{
    const double a = 170.0 / 255.0;
    return qRgb(int(colour.red() * a + qRed(map) * (1 - a)), int(colour.green() * a + qGreen(map) * (1 - a)),
                int(colour.blue() * a + qBlue(map) * (1 - a)));
}

} // namespace

class TestLayerCache : public QObject
{
    Q_OBJECT

    std::unique_ptr<QuickScene> m_scene;
    MapView *m_map = nullptr;
    RouteLayer *m_route = nullptr;
    VehicleLayer *m_vehicles = nullptr;
    CoordinateListModel *m_model = nullptr;

    QQuickView &view() { return m_scene->view(); }
    QImage grab() { return m_scene->grab(); }
    // Waypoint 2's marker body (left of its number), wherever the map has put it.
    QPointF markerBody() const { return m_route->waypointPosition(2) + QPointF(-6, 0); }

private slots:
    void initTestCase() { sortie::test::useSoftwareRendering(); }

    void init()
    {
        m_scene = std::make_unique<QuickScene>(kScene, QSize(800, 600));
        QVERIFY2(m_scene->isReady(), qPrintable(m_scene->errors()));
        m_map = m_scene->find<MapView>(QStringLiteral("map"));
        m_route = m_scene->find<RouteLayer>(QStringLiteral("route"));
        m_vehicles = m_scene->find<VehicleLayer>(QStringLiteral("vehicles"));
        QVERIFY(m_map && m_route && m_vehicles);
        m_model = new CoordinateListModel(m_scene->root());
        for (const QPointF &p : kWaypoints) {
            const QGeoCoordinate c = m_map->toCoordinate(p);
            m_model->append(c.latitude(), c.longitude(), 50);
        }
        m_route->setModel(m_model);
        m_route->setSelectionModel(new QItemSelectionModel(m_model, m_scene->root()));
        QTRY_VERIFY(near(grab(), markerBody(), kMarker));
    }

    void cleanup() { m_scene.reset(); }

    void panWithinTheMarginMovesThePicture()
    {
        // A pan at one zoom has a picture with a margin (there is none just after a zoom).
        m_map->panBy(1, 0);
        QCOMPARE(m_route->pictureMargin(), MapLayer::kDefaultPanMargin);
        m_map->panBy(-1, 0);
        const MapViewport laidOut = m_route->paintViewport();
        const QPointF before = markerBody();
        m_map->panBy(40, 30);
        QVERIFY(m_route->paintViewport() == laidOut); // not laid out again: moved
        QCOMPARE(m_route->paintOrigin(), QPointF(40 - m_route->pictureMargin(), 30 - m_route->pictureMargin()));
        const QImage moved = grab();
        QVERIFY(near(moved, markerBody(), kMarker));
        QVERIFY(!near(moved, before, kMarker));
        // Back where it was: the same picture in its first place.
        m_map->panBy(-40, -30);
        QVERIFY(m_route->paintViewport() == laidOut);
        QVERIFY(near(grab(), before, kMarker));
    }

    void panBeyondTheMarginDrawsAnew()
    {
        m_map->panBy(1, 0);
        const MapViewport laidOut = m_route->paintViewport();
        const QPointF before = markerBody();
        m_map->panBy(-(m_route->pictureMargin() + 20), 10);
        QVERIFY(!(m_route->paintViewport() == laidOut));
        QTRY_VERIFY(near(grab(), markerBody(), kMarker));
        QVERIFY(!near(grab(), before, kMarker));
        // Legs too: the middle of leg 2-3 at its new place.
        const QPointF leg = (m_route->waypointPosition(2) + m_route->waypointPosition(3)) / 2;
        QVERIFY(near(grab(), leg, kLeg));
    }

    void fractionalPanAndZoomDrawAnew()
    {
        const MapViewport laidOut = m_route->paintViewport();
        m_map->panBy(0.5, 0); // no whole-pixel move would be exact
        QVERIFY(!(m_route->paintViewport() == laidOut));
        QTRY_VERIFY(near(grab(), markerBody(), kMarker));
        const QPointF before = markerBody();
        m_map->zoomAroundPoint(QPointF(150, 150), m_map->zoomLevel() + 1);
        QCOMPARE(m_route->paintViewport().zoom(), m_map->zoomLevel());
        QCOMPARE(m_route->pictureMargin(), 0);
        QTRY_VERIFY(near(grab(), markerBody(), kMarker));
        QVERIFY(!near(grab(), before, kMarker));
        QVERIFY(near(grab(), (m_route->waypointPosition(0) + m_route->waypointPosition(1)) / 2, kLeg));
    }

    void dragDrawsTheMovedLegsAndNotTheOldOnes()
    {
        const QPointF oldLeg = (kWaypoints[0] + kWaypoints[1]) / 2;
        const QPointF oldMarker = kWaypoints[1] + QPointF(-6, 0);
        QVERIFY(near(grab(), oldLeg, kLeg));
        QTest::mousePress(&view(), Qt::LeftButton, {}, kWaypoints[1].toPoint());
        QTest::mouseMove(&view(), (kWaypoints[1] + QPointF(0, 60)).toPoint());
        QTest::mouseMove(&view(), (kWaypoints[1] + QPointF(0, 120)).toPoint());
        QVERIFY(m_route->isDragging());
        const QPointF dropped = kWaypoints[1] + QPointF(0, 120);
        QImage image = grab();
        QVERIFY(near(image, (kWaypoints[0] + dropped) / 2, kLeg));
        QVERIFY(near(image, (dropped + kWaypoints[2]) / 2, kLeg));
        QVERIFY(near(image, dropped + QPointF(-6, 0), kSelected));
        QVERIFY(!near(image, oldLeg, kLeg));
        QVERIFY(!near(image, (kWaypoints[1] + kWaypoints[2]) / 2, kLeg));
        QVERIFY(!near(image, oldMarker, kSelected) && !near(image, oldMarker, kMarker));
        // The legs that do not move stay drawn.
        QVERIFY(near(image, (kWaypoints[2] + kWaypoints[3]) / 2, kLeg));

        // Further: the overlay follows, leaving nothing at the previous mouse position.
        QTest::mouseMove(&view(), (kWaypoints[1] + QPointF(150, 120)).toPoint());
        image = grab();
        QVERIFY(!near(image, dropped + QPointF(-6, 0), kSelected));
        QVERIFY(near(image, kWaypoints[1] + QPointF(150 - 6, 120), kSelected));

        // Released and applied by the model's owner: drawn there from the model.
        QTest::mouseRelease(&view(), Qt::LeftButton, {}, (kWaypoints[1] + QPointF(150, 120)).toPoint());
        const QGeoCoordinate at = m_map->toCoordinate(kWaypoints[1] + QPointF(150, 120));
        m_model->setCoordinate(1, at.latitude(), at.longitude());
        QTRY_VERIFY(near(grab(), kWaypoints[1] + QPointF(150 - 6, 120), kSelected));
        QVERIFY(!near(grab(), oldLeg, kLeg));
        QVERIFY(near(grab(), (kWaypoints[0] + kWaypoints[1] + QPointF(150, 120)) / 2, kLeg));
    }

    void trailsFollowMovesZoomsColoursAndCuts()
    {
        QStandardItemModel model;
        model.setItemRoleNames({{IdRole, "vehicleId"}, {NameRole, "name"}, {LatRole, "latitude"}, {LonRole, "longitude"},
                                {StaleRole, "stale"}});
        auto place = [&](QPointF screen) {
            const QGeoCoordinate c = m_map->toCoordinate(screen);
            model.setItemData(model.index(0, 0), {{LatRole, c.latitude()}, {LonRole, c.longitude()}});
        };
        const QImage mapOnly = grab();
        auto *item = new QStandardItem;
        item->setData(QStringLiteral("v1"), IdRole);
        item->setData(false, StaleRole);
        model.appendRow(item);
        place(QPointF(100, 400));
        m_vehicles->setModel(&model);
        // Step by step east: each piece joins the trail (drawn frame by frame).
        for (int x = 120; x <= 400; x += 20) {
            place(QPointF(x, 400));
            grab();
        }
        QCOMPARE(m_vehicles->trailPointCount(0), 16);
        QImage image = grab();
        for (int x : {130, 210, 290, 350})
            QVERIFY2(colourDistance(image.pixel(x, 400), overMap(kFirstVehicle, mapOnly.pixel(x, 400))) < 24, qPrintable(QString::number(x)));
        QVERIFY(colourDistance(image.pixel(200, 390), mapOnly.pixel(200, 390)) < 24);

        // A zoom lays the trail out again where it now is.
        m_map->zoomAroundPoint(QPointF(200, 400), m_map->zoomLevel() + 1);
        m_vehicles->setTrailsVisible(false);
        const QImage zoomedMap = grab();
        m_vehicles->setTrailsVisible(true);
        QTRY_VERIFY(colourDistance(grab().pixel(100, 400), overMap(kFirstVehicle, zoomedMap.pixel(100, 400))) < 24);
        QVERIFY(colourDistance(grab().pixel(300, 400), overMap(kFirstVehicle, zoomedMap.pixel(300, 400))) < 24);
        QVERIFY(colourDistance(grab().pixel(300, 385), zoomedMap.pixel(300, 385)) < 24);

        // A stale vehicle's trail turns grey: drawn whole again in the new colour.
        item->setData(true, StaleRole);
        QTRY_VERIFY(colourDistance(grab().pixel(100, 400), overMap(QColor(0x90, 0x90, 0x90), zoomedMap.pixel(100, 400))) < 24);

        // Cut short: the old part disappears (at once here: the cut is more than the slack).
        m_vehicles->setTrailLength(3);
        QTRY_VERIFY(colourDistance(grab().pixel(100, 400), zoomedMap.pixel(100, 400)) < 24);
        QVERIFY(colourDistance(grab().pixel(100, 400), overMap(QColor(0x90, 0x90, 0x90), zoomedMap.pixel(100, 400))) >= 24);
    }
};

QTEST_MAIN(TestLayerCache)
#include "tst_layercache.moc"
