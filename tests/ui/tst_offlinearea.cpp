// The offline maps area drawn on the map, offscreen with the program's own wiring: Offline… →
// "Draw an area" puts the dialog away, the corners are clicked on the mission map with the zones'
// polygon tool, Done brings the dialog back with the area's tile count (the one TileArea counts for
// those corners) and shows the area on the map; a Shift+drag gives a rectangle; Cancel keeps the
// area there was; a crossing polygon is refused in the dialog, naming the crossing edges.
#include "ClientWindow.h"
#include "MapView.h"
#include "OfflineMaps.h"
#include "RouteDocument.h"
#include "TileArea.h"

#include <QDir>
#include <QSignalSpy>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {
QPointF centreOf(QQuickItem *item)
{
    return item->mapToScene(QPointF(item->width() / 2, item->height() / 2));
}

QString screenshotDir()
{
    return qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR));
}

void click(QQuickWindow *window, QPointF at)
{
    QTest::mouseClick(window, Qt::LeftButton, {}, at.toPoint());
}

// The tiles of the area's corners as OfflineMaps reports them, counted by TileArea itself.
double tilesOf(const maptiles::OfflineMaps &maps)
{
    QList<QPointF> lonLat;
    for (const QVariant &v : maps.areaCorners()) {
        const QGeoCoordinate c = v.value<QGeoCoordinate>();
        lonLat.append({c.longitude(), c.latitude()});
    }
    return double(maptiles::TileArea::polygon(lonLat).tileCount(maps.minimumZoom(), maps.maximumZoom()));
}
} // namespace

class TestOfflineArea : public QObject
{
    Q_OBJECT

private slots:
    void drawnOnTheMap()
    {
        test::ClientWindow client;
        QVERIFY2(client.isReady(), qPrintable(client.error()));
        client.showPage(1);
        maptiles::OfflineMaps &maps = client.graph().offlineMaps();
        maps.setMinimumZoom(12);
        maps.setMaximumZoom(17);
        client::RouteDocument *doc = client.missions().document();
        const int waypoints = doc->model()->rowCount();
        auto *map = client.page("missionPage")->property("map").value<ui::MapView *>();
        QVERIFY(map);
        // A 2 km box in the map's middle, clear of the zones button and the drawing bar.
        const QGeoCoordinate centre(56.95, 24.1);
        QTest::qWait(300); // the page's layout settled (its split views)
        map->fitBounds(56.93, 24.06, 56.97, 24.14, 150);
        QTest::qWait(100);
        const auto onMap = [map](const QGeoCoordinate &c) { return map->mapToScene(map->fromCoordinate(c)); };

        // Offline… → Draw an area: the dialog goes, the mission map's drawing bar comes.
        const auto openDialog = [&]() -> QObject * {
            click(client.window(), centreOf(client.find(QStringLiteral("offlineMapsButton"))));
            QObject *dialog = client.find<QObject>(QStringLiteral("offlineMapsDialog"));
            return dialog && QTest::qWaitFor([dialog] { return dialog->property("opened").toBool(); }) ? dialog : nullptr;
        };
        QObject *dialog = openDialog();
        QVERIFY(dialog);
        QVERIFY(!client.find(QStringLiteral("offlineAreaLayer"))->isVisible()); // no area yet
        const auto startDrawing = [&] {
            click(client.window(), centreOf(client.find(QStringLiteral("drawAreaButton"))));
            return QTest::qWaitFor([&] { return !dialog->property("visible").toBool() && client.find(QStringLiteral("offlineAreaBar"))->isVisible(); });
        };
        QVERIFY(startDrawing());
        QCOMPARE(client.window()->property("currentPage").toInt(), 1);

        // An L of five corners (concave: fewer tiles than its box), then Done.
        const QGeoCoordinate corners[] = {centre.atDistanceAndAzimuth(900, 225), centre.atDistanceAndAzimuth(900, 135),
                                          centre.atDistanceAndAzimuth(300, 100), centre.atDistanceAndAzimuth(300, 10),
                                          centre.atDistanceAndAzimuth(900, 315)};
        QQuickItem *done = client.find(QStringLiteral("finishAreaButton"));
        QVERIFY(!done->isEnabled());
        for (const QGeoCoordinate &c : corners)
            click(client.window(), onMap(c));
        QTRY_VERIFY(done->isEnabled());
        click(client.window(), centreOf(done));
        QTRY_VERIFY(dialog->property("opened").toBool());
        QVERIFY(!client.find(QStringLiteral("offlineAreaBar"))->isVisible());
        QCOMPARE(doc->model()->rowCount(), waypoints); // the clicks drew the area, not waypoints

        // The dialog's count is TileArea's for the clicked corners, each within a few metres.
        QVERIFY2(maps.problem().isEmpty(), qPrintable(maps.problem()));
        QCOMPARE(maps.areaCorners().size(), 5);
        for (int i = 0; i < 5; ++i)
            QVERIFY2(maps.areaCorners().at(i).value<QGeoCoordinate>().distanceTo(corners[i]) < 10,
                     qPrintable(QStringLiteral("corner %1 %2 m away").arg(i).arg(maps.areaCorners().at(i).value<QGeoCoordinate>().distanceTo(corners[i]))));
        QVERIFY(maps.tileCount() > 0);
        QCOMPARE(maps.tileCount(), tilesOf(maps));
        QVERIFY2(client.find<QObject>(QStringLiteral("areaLabel"))->property("text").toString().contains(QStringLiteral("(5 corner")),
                 qPrintable(client.find<QObject>(QStringLiteral("areaLabel"))->property("text").toString()));
        const QString estimate = client.find<QObject>(QStringLiteral("estimateLabel"))->property("text").toString();
        QVERIFY2(estimate.startsWith(QLocale().toString(qint64(maps.tileCount())) + QStringLiteral(" tiles")), qPrintable(estimate));
        // On the map while the dialog is open.
        QQuickItem *shown = client.find(QStringLiteral("offlineAreaLayer"));
        QTRY_VERIFY(shown->isVisible());
        QCOMPARE(shown->property("vertexCount").toInt(), 5);
        QVERIFY(test::waitForFrame(client.window()));
        client.window()->grabWindow().save(QDir(screenshotDir()).filePath(QStringLiteral("offline-area.png")));
        const double drawnCount = maps.tileCount();

        // Cancel keeps it.
        QVERIFY(startDrawing());
        click(client.window(), onMap(corners[0]));
        click(client.window(), centreOf(client.find(QStringLiteral("cancelAreaButton"))));
        QTRY_VERIFY(dialog->property("opened").toBool());
        QCOMPARE(maps.tileCount(), drawnCount);
        QCOMPARE(maps.areaCorners().size(), 5);

        // A bow tie: refused in the dialog, naming the edges; the L kept.
        QVERIFY(startDrawing());
        for (const QGeoCoordinate &c : {corners[0], corners[3], corners[1], corners[4]})
            click(client.window(), onMap(c));
        click(client.window(), centreOf(done));
        QTRY_VERIFY(dialog->property("opened").toBool());
        QObject *problem = client.find<QObject>(QStringLiteral("problemLabel"));
        QVERIFY2(problem->property("text").toString().contains(QStringLiteral("corner 1 and corner 3 cross")), qPrintable(problem->property("text").toString()));
        QVERIFY(client.find(QStringLiteral("problemLabel"))->isVisible());
        QCOMPARE(maps.tileCount(), drawnCount);

        // Shift+drag: a rectangle, corner to corner.
        QVERIFY(startDrawing());
        const QPoint from = onMap(corners[4]).toPoint(), to = onMap(corners[1]).toPoint();
        QTest::mousePress(client.window(), Qt::LeftButton, Qt::ShiftModifier, from);
        for (int i = 1; i <= 6; ++i)
            QTest::mouseMove(client.window(), from + (to - from) * i / 6);
        QTest::mouseRelease(client.window(), Qt::LeftButton, Qt::ShiftModifier, to);
        QTRY_VERIFY(dialog->property("opened").toBool());
        QVERIFY2(maps.problem().isEmpty(), qPrintable(maps.problem()));
        QCOMPARE(maps.areaCorners().size(), 4);
        const QGeoCoordinate northWest = maps.areaCorners().at(0).value<QGeoCoordinate>(), southEast = maps.areaCorners().at(2).value<QGeoCoordinate>();
        QVERIFY(northWest.distanceTo(corners[4]) < 10);
        QVERIFY(southEast.distanceTo(QGeoCoordinate(corners[1].latitude(), corners[1].longitude())) < 10);
        QCOMPARE(maps.tileCount(), double(maptiles::TileArea::rectangle({southEast.latitude(), northWest.longitude(), northWest.latitude(), southEast.longitude()})
                                              .tileCount(maps.minimumZoom(), maps.maximumZoom())));
        QVERIFY(maps.tileCount() > drawnCount); // the box holds more than the L
        QCOMPARE(doc->model()->rowCount(), waypoints);
    }
};

QTEST_MAIN(TestOfflineArea)
#include "tst_offlinearea.moc"
