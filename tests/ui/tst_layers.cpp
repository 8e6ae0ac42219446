// Route, area-scan and vehicle layers over a MapView in a real offscreen scene: hit testing,
// selection, waypoint drags, rubber band, rendering, 10,000 waypoints, trails and headings.
#include "AreaScanLayer.h"
#include "CoordinateListModel.h"
#include "MapView.h"
#include "QuickScene.h"
#include "RouteLayer.h"
#include "VehicleLayer.h"

#include <QItemSelectionModel>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <cmath>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie::ui;
using sortie::test::QuickScene;

namespace {

const QByteArray kScene = R"(
import QtQuick
import Sortie.Ui
Item {
    MapView {
        id: map
        objectName: "map"
        anchors.fill: parent
        latitude: 56.95
        longitude: 24.1
        zoomLevel: 14
        onAreaSelected: (rect, modifiers) => route.selectInRect(rect, modifiers)
    }
    AreaScanLayer { objectName: "area"; anchors.fill: parent; map: map; editable: true }
    RouteLayer { id: route; objectName: "route"; anchors.fill: parent; map: map; editable: true }
    VehicleLayer { objectName: "vehicles"; anchors.fill: parent; map: map }
}
)";

const QList<QPointF> kWaypoints{{150, 150}, {300, 200}, {450, 150}, {600, 250}, {600, 450}, {300, 450}};

enum VehicleRole { IdRole = Qt::UserRole + 1, NameRole, LatRole, LonRole, HeadingRole, HomeLatRole, HomeLonRole, StaleRole };

QList<int> rows(const QItemSelectionModel &selection)
{
    QList<int> out;
    for (const QModelIndex &index : selection.selectedRows())
        out.append(index.row());
    std::sort(out.begin(), out.end());
    return out;
}

int countNear(const QImage &image, const QRect &rect, const QColor &colour)
{
    int count = 0;
    for (int y = rect.top(); y <= rect.bottom(); ++y) {
        for (int x = rect.left(); x <= rect.right(); ++x)
            count += sortie::test::colourDistance(image.pixel(x, y), colour.rgb()) < 40 ? 1 : 0;
    }
    return count;
}

bool samePlace(const QGeoCoordinate &a, const QGeoCoordinate &b)
{
    return std::abs(a.latitude() - b.latitude()) < 1e-7 && std::abs(a.longitude() - b.longitude()) < 1e-7;
}

} // namespace

class TestLayers : public QObject
{
    Q_OBJECT

    std::unique_ptr<QuickScene> m_scene;
    MapView *m_map = nullptr;
    RouteLayer *m_route = nullptr;
    CoordinateListModel *m_model = nullptr;
    QItemSelectionModel *m_selection = nullptr;

    QQuickView &view() { return m_scene->view(); }

private slots:
    void initTestCase() { sortie::test::useSoftwareRendering(); }

    void init()
    {
        m_scene = std::make_unique<QuickScene>(kScene, QSize(800, 600));
        QVERIFY2(m_scene->isReady(), qPrintable(m_scene->errors()));
        m_map = m_scene->find<MapView>(QStringLiteral("map"));
        m_route = m_scene->find<RouteLayer>(QStringLiteral("route"));
        QVERIFY(m_map && m_route);
        m_model = new CoordinateListModel(m_scene->root());
        for (const QPointF &p : kWaypoints) {
            const QGeoCoordinate c = m_map->toCoordinate(p);
            m_model->append(c.latitude(), c.longitude(), 50);
        }
        m_selection = new QItemSelectionModel(m_model, m_scene->root());
        m_route->setModel(m_model);
        m_route->setSelectionModel(m_selection);
        QCOMPARE(m_route->count(), 6);
    }

    void cleanup() { m_scene.reset(); }

    void hitTesting()
    {
        for (int i = 0; i < kWaypoints.size(); ++i) {
            QVERIFY((m_route->waypointPosition(i) - kWaypoints[i]).manhattanLength() < 1e-6);
            QCOMPARE(m_route->waypointAt(kWaypoints[i] + QPointF(5, -4)), i);
        }
        QCOMPARE(m_route->waypointAt(QPointF(20, 20)), -1);
        QCOMPARE(m_route->legAt((kWaypoints[0] + kWaypoints[1]) / 2), 0);
        QCOMPARE(m_route->legAt((kWaypoints[4] + kWaypoints[5]) / 2 + QPointF(0, 4)), 4);
        QCOMPARE(m_route->legAt((kWaypoints[4] + kWaypoints[5]) / 2 + QPointF(0, 12)), -1);
        QCOMPARE(m_route->waypointsIn(QRectF(100, 100, 400, 120)), (QList<int>{0, 1, 2}));
    }

    void clicksSelect()
    {
        QSignalSpy clicked(m_route, &RouteLayer::waypointClicked);
        QTest::mouseClick(&view(), Qt::LeftButton, {}, kWaypoints[2].toPoint());
        QCOMPARE(rows(*m_selection), (QList<int>{2}));
        QCOMPARE(m_selection->currentIndex().row(), 2);
        QTest::mouseClick(&view(), Qt::LeftButton, Qt::ControlModifier, kWaypoints[4].toPoint());
        QCOMPARE(rows(*m_selection), (QList<int>{2, 4}));
        QTest::mouseClick(&view(), Qt::LeftButton, Qt::ShiftModifier, kWaypoints[5].toPoint());
        QCOMPARE(rows(*m_selection), (QList<int>{2, 4, 5}));
        QTest::mouseClick(&view(), Qt::LeftButton, Qt::ControlModifier, kWaypoints[2].toPoint());
        QCOMPARE(rows(*m_selection), (QList<int>{4, 5}));
        QCOMPARE(clicked.count(), 4);
        QCOMPARE(clicked.at(1).at(1).toInt(), int(Qt::ControlModifier));
    }

    void dragMovesOneWaypoint()
    {
        QSignalSpy moved(m_route, &RouteLayer::waypointsMoved);
        const QGeoCoordinate centre = m_map->center();
        QTest::mousePress(&view(), Qt::LeftButton, {}, QPoint(600, 250));
        QTest::mouseMove(&view(), QPoint(620, 265));
        QVERIFY(m_route->isDragging());
        QTest::mouseMove(&view(), QPoint(640, 280));
        QTest::mouseRelease(&view(), Qt::LeftButton, {}, QPoint(640, 280));
        QVERIFY(!m_route->isDragging());
        QCOMPARE(moved.count(), 1);
        QCOMPARE(moved.at(0).at(0).value<QList<int>>(), QList<int>{3});
        const QGeoCoordinate dropped = moved.at(0).at(1).value<QList<QGeoCoordinate>>().at(0);
        QVERIFY(samePlace(dropped, m_map->toCoordinate(QPointF(640, 280))));
        QVERIFY(samePlace(m_map->center(), centre)); // the map did not pan
        // The layer only previewed: the model moves when its owner applies the move.
        QVERIFY((m_route->waypointPosition(3) - kWaypoints[3]).manhattanLength() < 1e-6);
        m_model->setCoordinate(3, dropped.latitude(), dropped.longitude());
        QVERIFY((m_route->waypointPosition(3) - QPointF(640, 280)).manhattanLength() < 1e-6);
    }

    void dragMovesTheSelection()
    {
        QTest::mouseClick(&view(), Qt::LeftButton, {}, kWaypoints[0].toPoint());
        QTest::mouseClick(&view(), Qt::LeftButton, Qt::ControlModifier, kWaypoints[1].toPoint());
        QSignalSpy moved(m_route, &RouteLayer::waypointsMoved);
        QTest::mousePress(&view(), Qt::LeftButton, {}, kWaypoints[1].toPoint());
        QTest::mouseMove(&view(), (kWaypoints[1] + QPointF(10, 5)).toPoint());
        QTest::mouseMove(&view(), (kWaypoints[1] + QPointF(20, 10)).toPoint());
        QTest::mouseRelease(&view(), Qt::LeftButton, {}, (kWaypoints[1] + QPointF(20, 10)).toPoint());
        QCOMPARE(moved.count(), 1);
        QCOMPARE(moved.at(0).at(0).value<QList<int>>(), (QList<int>{0, 1}));
        const auto coordinates = moved.at(0).at(1).value<QList<QGeoCoordinate>>();
        QVERIFY(samePlace(coordinates.at(0), m_map->toCoordinate(kWaypoints[0] + QPointF(20, 10))));
        QVERIFY(samePlace(coordinates.at(1), m_map->toCoordinate(kWaypoints[1] + QPointF(20, 10))));
    }

    void pressBesideTheRoutePansTheMap()
    {
        QSignalSpy moved(m_route, &RouteLayer::waypointsMoved);
        const QGeoCoordinate expected = m_map->toCoordinate(QPointF(400 - 60, 300 - 40));
        QTest::mousePress(&view(), Qt::LeftButton, {}, QPoint(720, 80));
        QTest::mouseMove(&view(), QPoint(750, 100));
        QTest::mouseMove(&view(), QPoint(780, 120));
        QTest::mouseRelease(&view(), Qt::LeftButton, {}, QPoint(780, 120));
        QCOMPARE(moved.count(), 0);
        QVERIFY(samePlace(m_map->center(), expected));
        // The route moved with the map.
        QVERIFY((m_route->waypointPosition(0) - (kWaypoints[0] + QPointF(60, 40))).manhattanLength() < 1e-6);
    }

    void clickOnALeg()
    {
        QSignalSpy leg(m_route, &RouteLayer::legClicked);
        QSignalSpy mapClicked(m_map, &MapView::clicked);
        const QPoint middle = ((kWaypoints[3] + kWaypoints[4]) / 2).toPoint();
        QTest::mouseClick(&view(), Qt::LeftButton, {}, middle);
        QCOMPARE(leg.count(), 1);
        QCOMPARE(leg.at(0).at(0).toInt(), 3);
        QVERIFY(samePlace(leg.at(0).at(1).value<QGeoCoordinate>(), m_map->toCoordinate(middle)));
        QCOMPARE(mapClicked.count(), 0);
        QTest::mouseClick(&view(), Qt::LeftButton, {}, QPoint(40, 560));
        QCOMPARE(mapClicked.count(), 1);
        QCOMPARE(leg.count(), 1);
    }

    void rubberBand()
    {
        QTest::mousePress(&view(), Qt::LeftButton, Qt::ShiftModifier, QPoint(100, 100));
        QTest::mouseMove(&view(), QPoint(300, 180));
        QTest::mouseMove(&view(), QPoint(500, 230));
        QTest::mouseRelease(&view(), Qt::LeftButton, Qt::ShiftModifier, QPoint(500, 230));
        QCOMPARE(rows(*m_selection), (QList<int>{0, 1, 2}));
        // Ctrl+Shift adds to the selection.
        QTest::mousePress(&view(), Qt::LeftButton, Qt::ShiftModifier | Qt::ControlModifier, QPoint(550, 400));
        QTest::mouseMove(&view(), QPoint(600, 430));
        QTest::mouseMove(&view(), QPoint(650, 500));
        QTest::mouseRelease(&view(), Qt::LeftButton, Qt::ShiftModifier | Qt::ControlModifier, QPoint(650, 500));
        QCOMPARE(rows(*m_selection), (QList<int>{0, 1, 2, 4}));
    }

    void drawsWaypointsAndSelection()
    {
        const QPoint onMarker = (kWaypoints[2] + QPointF(-6, 0)).toPoint();
        QTRY_VERIFY(sortie::test::colourDistance(m_scene->grab().pixel(onMarker), QColor(0x1e, 0x88, 0xe5).darker(130).rgb()) < 40);
        m_selection->select(m_model->index(2), QItemSelectionModel::ClearAndSelect);
        QTRY_VERIFY(sortie::test::colourDistance(m_scene->grab().pixel(onMarker), QColor(0xff, 0x8f, 0x00).rgb()) < 40);
        // A leg is drawn between waypoints 0 and 1.
        const QPoint onLeg = ((kWaypoints[0] + kWaypoints[1]) / 2).toPoint();
        QVERIFY(sortie::test::colourDistance(m_scene->grab().pixel(onLeg), QColor(0x1e, 0x88, 0xe5).rgb()) < 40);
    }

    void actionMarksBadgeTheirWaypoints()
    {
        // Any model with the roles: a camera badge on waypoint 1, none on 2, then other actions there.
        enum { Lat = Qt::UserRole + 1, Lon, Marks };
        auto *model = new QStandardItemModel(m_scene->root());
        model->setItemRoleNames({{Lat, "lat"}, {Lon, "lon"}, {Marks, "marks"}});
        for (int i = 0; i < 2; ++i) {
            const QGeoCoordinate c = m_map->toCoordinate(kWaypoints[i]);
            auto *item = new QStandardItem;
            item->setData(c.latitude(), Lat);
            item->setData(c.longitude(), Lon);
            item->setData(i == 0 ? 1 : 0, Marks);
            model->appendRow(item);
        }
        m_route->setSelectionModel(nullptr);
        m_route->setLatitudeRole(QStringLiteral("lat"));
        m_route->setLongitudeRole(QStringLiteral("lon"));
        m_route->setModel(model);
        m_route->setActionMarksRole(QStringLiteral("marks"));
        const QColor camera(0x2e, 0x7d, 0x32), other(0x6a, 0x1b, 0x9a);
        const auto badgeArea = [](int i) { return QRect((kWaypoints[i] + QPointF(2, -18)).toPoint(), QSize(18, 12)); };
        QTRY_VERIFY(countNear(m_scene->grab(), badgeArea(0), camera) > 10);
        QCOMPARE(countNear(m_scene->grab(), badgeArea(1), camera), 0);
        QCOMPARE(countNear(m_scene->grab(), badgeArea(1), other), 0);
        model->item(1)->setData(2, Marks);
        QTRY_VERIFY(countNear(m_scene->grab(), badgeArea(1), other) > 10);
        // No role, no badges.
        m_route->setActionMarksRole(QString());
        QTRY_COMPARE(countNear(m_scene->grab(), badgeArea(0), camera), 0);
    }

    void tenThousandWaypoints()
    {
        std::vector<QGeoCoordinate> points;
        for (int i = 0; i < 10000; ++i)
            points.emplace_back(56.9 + (i / 100) * 0.001, 24.0 + (i % 100) * 0.002);
        m_model->assign(points);
        QCOMPARE(m_route->count(), 10000);
        m_route->fitToMap(20);
        QTRY_COMPARE(m_route->visibleWaypointCount(), 10000);
        QVERIFY(m_route->labelledWaypointCount() > 10);
        QVERIFY(m_route->labelledWaypointCount() < 2000); // the rest are dots, not a smear of numbers
        m_map->setZoomLevel(m_map->zoomLevel() + 3);
        QTRY_VERIFY(m_route->visibleWaypointCount() < 10000 / 16);
        QVERIFY(m_route->waypointAt(m_route->waypointPosition(5050)) == 5050);
    }

    void vehiclesHeadingTrailAndHome()
    {
        auto *layer = m_scene->find<VehicleLayer>(QStringLiteral("vehicles"));
        QVERIFY(layer);
        QStandardItemModel model;
        model.setItemRoleNames({{IdRole, "vehicleId"}, {NameRole, "name"}, {LatRole, "latitude"}, {LonRole, "longitude"},
                                {HeadingRole, "heading"}, {HomeLatRole, "homeLatitude"}, {HomeLonRole, "homeLongitude"},
                                {StaleRole, "stale"}});
        const QGeoCoordinate at = m_map->toCoordinate(QPointF(400, 300));
        const QGeoCoordinate home = m_map->toCoordinate(QPointF(200, 500));
        for (int i = 0; i < 2; ++i) {
            auto *item = new QStandardItem;
            item->setData(QStringLiteral("v%1").arg(i), IdRole);
            item->setData(QStringLiteral("Drone %1").arg(i + 1), NameRole);
            item->setData(at.latitude() - i * 0.01, LatRole);
            item->setData(at.longitude(), LonRole);
            item->setData(0.0, HeadingRole);
            if (i == 0) { // the second vehicle does not know its home
                item->setData(home.latitude(), HomeLatRole);
                item->setData(home.longitude(), HomeLonRole);
            }
            item->setData(false, StaleRole);
            model.appendRow(item);
        }
        layer->setModel(&model);
        QCOMPARE(layer->count(), 2);
        QVERIFY((layer->vehiclePosition(0) - QPointF(400, 300)).manhattanLength() < 1e-6);
        QCOMPARE(layer->vehicleAt(QPointF(404, 296)), 0);

        // Heading 0: the arrow's tip is above the vehicle; 90: to its right.
        const QColor first(0xd8, 0x1b, 0x60);
        const QRect above(398, 291, 5, 5);
        const QRect right(405, 298, 5, 5);
        QTRY_VERIFY(countNear(m_scene->grab(), above, first) > 3);
        QCOMPARE(countNear(m_scene->grab(), right, first), 0);
        model.item(0)->setData(90.0, HeadingRole);
        QTRY_VERIFY(countNear(m_scene->grab(), right, first) > 3);
        QCOMPARE(countNear(m_scene->grab(), above, first), 0);

        // The home marker is drawn where home is.
        QVERIFY(countNear(m_scene->grab(), QRect(194, 494, 3, 12), first.darker(120)) > 10);

        // Each move adds to the trail; a repeat of the same position does not.
        for (int step = 1; step <= 5; ++step)
            model.item(0)->setData(at.longitude() + step * 0.001, LonRole);
        model.item(0)->setData(at.longitude() + 5 * 0.001, LonRole);
        QCOMPARE(layer->trailPointCount(0), 6);
        QCOMPARE(layer->trailPointCount(1), 1);
        layer->setTrailLength(3);
        QCOMPARE(layer->trailPointCount(0), 3);

        // Stale vehicles are grey.
        model.item(0)->setData(true, StaleRole);
        const QRect body(layer->vehiclePosition(0).toPoint() + QPoint(-2, -2), QSize(5, 5));
        QTRY_VERIFY(countNear(m_scene->grab(), body, QColor(0x90, 0x90, 0x90)) > 10);
        QCOMPARE(countNear(m_scene->grab(), body, first), 0);

        QSignalSpy clicked(layer, &VehicleLayer::vehicleClicked);
        QTest::mouseClick(&view(), Qt::LeftButton, {}, layer->vehiclePosition(1).toPoint());
        QCOMPARE(clicked.count(), 1);
        QCOMPARE(layer->currentIndex(), 1);
    }

    void vehiclesAtOneSpotKeepTheirLabelsApart()
    {
        auto *layer = m_scene->find<VehicleLayer>(QStringLiteral("vehicles"));
        QStandardItemModel model;
        model.setItemRoleNames({{IdRole, "vehicleId"}, {NameRole, "name"}, {LatRole, "latitude"}, {LonRole, "longitude"}});
        const QGeoCoordinate at = m_map->toCoordinate(QPointF(400, 300));
        for (int i = 0; i < 3; ++i) { // three vehicles on one spot (on the ground at one site)
            auto *item = new QStandardItem;
            item->setData(QStringLiteral("v%1").arg(i), IdRole);
            item->setData(QStringLiteral("EMU-10%1").arg(i + 1), NameRole);
            item->setData(at.latitude(), LatRole);
            item->setData(at.longitude(), LonRole);
            model.appendRow(item);
        }
        layer->setModel(&model);
        QTRY_VERIFY(!layer->labelRect(2).isEmpty());
        for (int a = 0; a < 3; ++a)
            for (int b = a + 1; b < 3; ++b)
                QVERIFY2(!layer->labelRect(a).intersects(layer->labelRect(b)), qPrintable(QStringLiteral("%1 and %2").arg(a).arg(b)));
        // The current vehicle's label goes first: beside its arrow, the others stacked below.
        layer->setCurrentIndex(2);
        QTRY_VERIFY(layer->labelRect(2).top() < layer->labelRect(0).top());
        QVERIFY(layer->labelRect(2).top() < layer->labelRect(1).top());
        QVERIFY(std::abs(layer->labelRect(2).center().y() - 290) < 4); // 10 px above the vehicle, as alone
        // And it stands out: its tag is filled with its colour, the yellow ring around it.
        const QImage image = m_scene->grab();
        QVERIFY(countNear(image, layer->labelRect(2).toRect().adjusted(3, 3, -3, -3), QColor(0x00, 0x89, 0x7b)) > 20);
        QVERIFY(countNear(image, QRect(418, 296, 6, 8), QColor(0xff, 0xd6, 0x00)) > 5);
    }

    void framesFollowsAndStopsWhenTheOperatorMovesTheMap()
    {
        auto *layer = m_scene->find<VehicleLayer>(QStringLiteral("vehicles"));
        QStandardItemModel model;
        model.setItemRoleNames({{IdRole, "vehicleId"}, {NameRole, "name"}, {LatRole, "latitude"}, {LonRole, "longitude"}});
        m_map->setZoomLevel(2); // the world
        layer->setAutoFit(true);
        layer->setModel(&model);
        QCOMPARE(layer->positionedCount(), 0);
        auto add = [&](double lat, double lon) {
            auto *item = new QStandardItem;
            item->setData(QStringLiteral("v%1").arg(model.rowCount()), IdRole);
            item->setData(QStringLiteral("V%1").arg(model.rowCount()), NameRole);
            item->setData(lat, LatRole);
            item->setData(lon, LonRole);
            model.appendRow(item);
        };
        // The first vehicle to report is framed (not at the closest zoom: about 400 m across).
        add(56.95, 24.10);
        QVERIFY(m_map->zoomLevel() > 14 && m_map->zoomLevel() < 18);
        QVERIFY((layer->vehiclePosition(0) - QPointF(400, 300)).manhattanLength() < 2);
        // A second one two kilometres away: both framed.
        add(56.95, 24.135);
        const QRectF inside(0, 0, 800, 600);
        QVERIFY(inside.contains(layer->vehiclePosition(0)) && inside.contains(layer->vehiclePosition(1)));
        QVERIFY(layer->autoFit());
        // The operator pans: autoFit stops, a third vehicle does not move the map.
        m_map->panBy(50, 0);
        QVERIFY(!layer->autoFit());
        const double zoom = m_map->zoomLevel();
        add(57.5, 25.0);
        QCOMPARE(m_map->zoomLevel(), zoom);
        // Fit all frames the three; centerOn puts one in the middle.
        QVERIFY(layer->fitToMap());
        for (int row = 0; row < 3; ++row)
            QVERIFY(inside.contains(layer->vehiclePosition(row)));
        QVERIFY(layer->centerOn(1));
        QVERIFY((layer->vehiclePosition(1) - QPointF(400, 300)).manhattanLength() < 2);
        // Follow: when the current vehicle leaves the middle half, it is brought back to the middle.
        layer->setCurrentIndex(1);
        layer->setFollow(true);
        m_map->setZoomLevel(16);
        model.item(1)->setData(24.135 + 0.006, LonRole); // some 360 m east: out of the middle at zoom 16
        QVERIFY((layer->vehiclePosition(1) - QPointF(400, 300)).manhattanLength() < 2);
        layer->setFollow(false);
        model.item(1)->setData(24.135 + 0.014, LonRole);
        QVERIFY((layer->vehiclePosition(1) - QPointF(400, 300)).manhattanLength() > 100);
    }

    void areaScanPolygon()
    {
        auto *layer = m_scene->find<AreaScanLayer>(QStringLiteral("area"));
        QVERIFY(layer);
        m_route->setModel(nullptr);
        CoordinateListModel polygon;
        CoordinateListModel transects;
        const QList<QPointF> corners{{200, 200}, {600, 200}, {600, 400}, {200, 400}};
        for (const QPointF &p : corners) {
            const QGeoCoordinate c = m_map->toCoordinate(p);
            polygon.append(c.latitude(), c.longitude());
        }
        for (int x = 220; x <= 580; x += 40) {
            for (int y : {x % 80 == 60 ? 220 : 380, x % 80 == 60 ? 380 : 220}) {
                const QGeoCoordinate c = m_map->toCoordinate(QPointF(x, y));
                transects.append(c.latitude(), c.longitude());
            }
        }
        layer->setPolygonModel(&polygon);
        layer->setTransectModel(&transects);
        QCOMPARE(layer->vertexCount(), 4);
        QCOMPARE(layer->transectPointCount(), 20);
        QCOMPARE(layer->vertexAt(QPointF(603, 398)), 2);
        QCOMPARE(layer->edgeAt(QPointF(400, 402)), 2);
        QCOMPARE(layer->edgeAt(QPointF(198, 300)), 3); // the closing edge
        QCOMPARE(layer->edgeAt(QPointF(400, 300)), -1);

        QSignalSpy moved(layer, &AreaScanLayer::vertexMoved);
        QTest::mousePress(&view(), Qt::LeftButton, {}, QPoint(600, 200));
        QTest::mouseMove(&view(), QPoint(630, 190));
        QTest::mouseMove(&view(), QPoint(650, 180));
        QTest::mouseRelease(&view(), Qt::LeftButton, {}, QPoint(650, 180));
        // Every step of the drag is reported (Continuing), then the drop (Done): the owner can
        // apply it live and merge the steps into one undo step.
        QCOMPARE(moved.count(), 3);
        QCOMPARE(moved.at(0).at(2).value<sortie::mission::EditStep>(), sortie::mission::EditStep::Continuing);
        QVERIFY(samePlace(moved.at(0).at(1).value<QGeoCoordinate>(), m_map->toCoordinate(QPointF(630, 190))));
        QCOMPARE(moved.last().at(0).toInt(), 1);
        QCOMPARE(moved.last().at(2).value<sortie::mission::EditStep>(), sortie::mission::EditStep::Done);
        QVERIFY(samePlace(moved.last().at(1).value<QGeoCoordinate>(), m_map->toCoordinate(QPointF(650, 180))));
        // A right click on a corner asks for its removal.
        QSignalSpy removal(layer, &AreaScanLayer::vertexRemoveRequested);
        QTest::mouseClick(&view(), Qt::RightButton, {}, QPoint(603, 398));
        QCOMPARE(removal.count(), 1);
        QCOMPARE(removal.at(0).at(0).toInt(), 2);

        // Inside the polygon the fill is a tint of the layer's green over the map.
        const QRgb inside = m_scene->grab().pixel(250, 300);
        QVERIFY(qGreen(inside) > qRed(inside));
    }
};

QTEST_MAIN(TestLayers)
#include "tst_layers.moc"
