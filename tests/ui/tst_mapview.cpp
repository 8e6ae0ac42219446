// MapView in a real offscreen QML scene (software scene graph), driven by simulated mouse,
// wheel, keys and touch; what it draws checked pixel by pixel.
#include "MapPalette.h"
#include "MapScaleBar.h"
#include "MapView.h"
#include "QuickScene.h"
#include "Theme.h"
#include "TileHttpServer.h"
#include "XyzTileSource.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <memory>
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
        latitude: 20
        longitude: 0
        zoomLevel: 3
    }
    MapScaleBar {
        objectName: "scaleBar"
        map: map
        width: 140
        height: 26
    }
}
)";

bool near(const QGeoCoordinate &a, const QGeoCoordinate &b, double tolerance = 1e-6)
{
    return std::abs(a.latitude() - b.latitude()) < tolerance && std::abs(a.longitude() - b.longitude()) < tolerance;
}

QString describe(const QGeoCoordinate &c)
{
    return QStringLiteral("%1, %2").arg(c.latitude(), 0, 'f', 8).arg(c.longitude(), 0, 'f', 8);
}

} // namespace

class TestMapView : public QObject
{
    Q_OBJECT

    std::unique_ptr<QuickScene> m_scene;
    MapView *m_map = nullptr;

    QColor colourAt(const QGeoCoordinate &coordinate)
    {
        const QPointF p = m_map->fromCoordinate(coordinate);
        return m_scene->grab().pixelColor(p.toPoint());
    }

private slots:
    void initTestCase() { sortie::test::useSoftwareRendering(); }

    void init()
    {
        m_scene = std::make_unique<QuickScene>(kScene, QSize(800, 600));
        QVERIFY2(m_scene->isReady(), qPrintable(m_scene->errors()));
        m_map = m_scene->find<MapView>(QStringLiteral("map"));
        QVERIFY(m_map);
        QCOMPARE(m_map->width(), 800.0);
    }

    void cleanup()
    {
        m_scene.reset();
        m_map = nullptr;
    }

    void propertiesFromQml()
    {
        QVERIFY(std::abs(m_map->latitude() - 20) < 1e-9);
        QVERIFY(std::abs(m_map->longitude()) < 1e-9);
        QCOMPARE(m_map->zoomLevel(), 3.0);
        QCOMPARE(m_map->tileStatus(), QStringLiteral("Offline base map"));
        const QPointF middle = m_map->fromCoordinate(m_map->center());
        QVERIFY(std::abs(middle.x() - 400) < 1e-6 && std::abs(middle.y() - 300) < 1e-6);
    }

    void offlineBaseMapIsNeverBlank()
    {
        // No tile server anywhere: land and sea come from the built-in outlines.
        QTRY_COMPARE(colourAt(QGeoCoordinate(23, 10)), MapPalette::light().land);   // Sahara
        QCOMPARE(colourAt(QGeoCoordinate(25, -40)), MapPalette::light().sea);       // Atlantic
        const QImage image = m_scene->grab();
        QVERIFY(sortie::test::distinctColours(image) > 4); // land, sea, coast, graticule, labels

        // The theme's scheme changes the map's palette, and the map draws again in it.
        Theme theme;
        theme.setScheme(Theme::Scheme::Dark);
        m_map->setTheme(&theme);
        QTRY_COMPARE(colourAt(QGeoCoordinate(23, 10)), MapPalette::dark().land);
        QCOMPARE(colourAt(QGeoCoordinate(25, -40)), MapPalette::dark().sea);
        theme.setScheme(Theme::Scheme::Sunlight);
        QTRY_COMPARE(colourAt(QGeoCoordinate(23, 10)), MapPalette::sunlight().land);
        QCOMPARE(colourAt(QGeoCoordinate(25, -40)), MapPalette::sunlight().sea);
        m_map->setTheme(nullptr);
        QTRY_COMPARE(colourAt(QGeoCoordinate(23, 10)), MapPalette::light().land);
    }

    void dragPans()
    {
        const QGeoCoordinate expected = m_map->toCoordinate(QPointF(300, 250));
        QSignalSpy clicked(m_map, &MapView::clicked);
        QTest::mousePress(&m_scene->view(), Qt::LeftButton, {}, QPoint(400, 300));
        QTest::mouseMove(&m_scene->view(), QPoint(430, 315));
        QTest::mouseMove(&m_scene->view(), QPoint(470, 335));
        QTest::mouseMove(&m_scene->view(), QPoint(500, 350));
        QTest::mouseRelease(&m_scene->view(), Qt::LeftButton, {}, QPoint(500, 350));
        QVERIFY2(near(m_map->center(), expected), qPrintable(describe(m_map->center()) + " vs " + describe(expected)));
        QCOMPARE(clicked.count(), 0);
    }

    void clickReportsTheCoordinate()
    {
        QSignalSpy clicked(m_map, &MapView::clicked);
        const QGeoCoordinate expected = m_map->toCoordinate(QPointF(123, 456));
        QTest::mouseClick(&m_scene->view(), Qt::LeftButton, Qt::ControlModifier, QPoint(123, 456));
        QCOMPARE(clicked.count(), 1);
        QVERIFY(near(clicked.at(0).at(0).value<QGeoCoordinate>(), expected));
        QCOMPARE(clicked.at(0).at(1).toInt(), int(Qt::ControlModifier));
        QVERIFY(near(m_map->center(), QGeoCoordinate(20, 0)));
    }

    void shiftDragSelectsARectangle()
    {
        QSignalSpy selected(m_map, &MapView::areaSelected);
        QTest::mousePress(&m_scene->view(), Qt::LeftButton, Qt::ShiftModifier, QPoint(100, 100));
        QTest::mouseMove(&m_scene->view(), QPoint(200, 160));
        QCOMPARE(m_map->selectionRect(), QRectF(100, 100, 100, 60));
        QTest::mouseMove(&m_scene->view(), QPoint(250, 200));
        QTest::mouseRelease(&m_scene->view(), Qt::LeftButton, Qt::ShiftModifier, QPoint(250, 200));
        QCOMPARE(selected.count(), 1);
        QCOMPARE(selected.at(0).at(0).toRectF(), QRectF(100, 100, 150, 100));
        QVERIFY(m_map->selectionRect().isEmpty());
        QVERIFY(near(m_map->center(), QGeoCoordinate(20, 0))); // no pan
    }

    void wheelZoomsAroundTheCursor()
    {
        const QPointF at(600, 150);
        const QGeoCoordinate under = m_map->toCoordinate(at);
        QWheelEvent up(at, m_scene->view().mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                       Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(&m_scene->view(), &up);
        QCOMPARE(m_map->zoomLevel(), 3.5);
        const QPointF still = m_map->fromCoordinate(under);
        QVERIFY2(std::abs(still.x() - at.x()) < 1e-6 && std::abs(still.y() - at.y()) < 1e-6,
                 qPrintable(QStringLiteral("%1,%2").arg(still.x()).arg(still.y())));
        QWheelEvent down(at, m_scene->view().mapToGlobal(at), QPoint(), QPoint(0, -360), Qt::NoButton, Qt::NoModifier,
                         Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(&m_scene->view(), &down);
        QCOMPARE(m_map->zoomLevel(), 2.0);
    }

    void keysPanAndZoom()
    {
        m_map->forceActiveFocus();
        QVERIFY(m_map->hasActiveFocus());
        const QGeoCoordinate west = m_map->toCoordinate(QPointF(400 - 80, 300));
        QTest::keyClick(&m_scene->view(), Qt::Key_Left);
        QVERIFY2(near(m_map->center(), west), qPrintable(describe(m_map->center())));
        const QGeoCoordinate south = m_map->toCoordinate(QPointF(400, 300 + 4 * 80));
        QTest::keyClick(&m_scene->view(), Qt::Key_Down, Qt::ShiftModifier);
        QVERIFY2(near(m_map->center(), south), qPrintable(describe(m_map->center())));
        QTest::keyClick(&m_scene->view(), Qt::Key_Plus);
        QCOMPARE(m_map->zoomLevel(), 4.0);
        QTest::keyClick(&m_scene->view(), Qt::Key_Minus);
        QTest::keyClick(&m_scene->view(), Qt::Key_Minus);
        QCOMPARE(m_map->zoomLevel(), 2.0);
        QVERIFY(near(m_map->center(), south)); // zooming with keys keeps the centre
    }

    void pinchZooms()
    {
        // The test owns the device it makes up (deleting it unregisters it).
        const std::unique_ptr<QPointingDevice> device(QTest::createTouchDevice());
        QPointingDevice *touch = device.get();
        const QGeoCoordinate middle = m_map->toCoordinate(QPointF(400, 300));
        QTest::touchEvent(&m_scene->view(), touch).press(0, QPoint(350, 300)).press(1, QPoint(450, 300));
        QTest::touchEvent(&m_scene->view(), touch).move(0, QPoint(325, 300)).move(1, QPoint(475, 300));
        QTest::touchEvent(&m_scene->view(), touch).move(0, QPoint(300, 300)).move(1, QPoint(500, 300));
        QTest::touchEvent(&m_scene->view(), touch).release(0, QPoint(300, 300)).release(1, QPoint(500, 300));
        // Fingers twice as far apart: one zoom level in, around the point between them.
        QVERIFY2(std::abs(m_map->zoomLevel() - 4.0) < 1e-9, qPrintable(QString::number(m_map->zoomLevel())));
        QVERIFY2(near(m_map->toCoordinate(QPointF(400, 300)), middle), qPrintable(describe(m_map->center())));
    }

    void cursorCoordinateFollowsTheMouse()
    {
        QSignalSpy cursor(m_map, &MapView::cursorChanged);
        QTest::mouseMove(&m_scene->view(), QPoint(220, 180));
        QTRY_VERIFY(m_map->isCursorInside());
        QVERIFY(near(m_map->cursorCoordinate(), m_map->toCoordinate(QPointF(220, 180))));
        QVERIFY(cursor.count() >= 1);
    }

    void scaleBarMeasuresTheMap()
    {
        auto *bar = m_scene->find<MapScaleBar>(QStringLiteral("scaleBar"));
        QVERIFY(bar);
        QVERIFY(!bar->label().isEmpty());
        QVERIFY(bar->barWidth() > 0 && bar->barWidth() <= 136);
        const QString before = bar->label();
        m_map->setZoomLevel(15);
        QVERIFY(bar->label() != before);
        QVERIFY(bar->label().endsWith(QStringLiteral(" m"))); // metres at street level
        bar->setImperial(true);
        QVERIFY(bar->label().endsWith(QStringLiteral(" ft")));
    }

    void webTilesCoverTheBaseMap()
    {
        QTemporaryDir cache;
        sortie::test::TileHttpServer server;
        QVERIFY(server.listen());
        XyzTileSource source;
        source.setCacheDirectory(cache.path());
        source.setUrlTemplate(server.urlTemplate());
        m_map->setTileSource(&source);
        // The tile under the centre at zoom 3: 20N 0E is tile 3/4/3.
        QTRY_COMPARE(colourAt(QGeoCoordinate(20, 0.5)), sortie::test::TileHttpServer::colourFor(3, 4, 3));
        QTRY_COMPARE(m_map->tileStatus(), server.urlTemplate().section(QLatin1Char('/'), 2, 2).section(QLatin1Char(':'), 0, 0));
        QVERIFY(server.requests() >= 4);
    }

    void unreachableServerFallsBackToTheBaseMap()
    {
        sortie::test::TileHttpServer server;
        QVERIFY(server.listen());
        const QString urlTemplate = server.urlTemplate();
        server.close();
        QTemporaryDir cache;
        XyzTileSource source;
        source.setCacheDirectory(cache.path());
        source.setUrlTemplate(urlTemplate);
        m_map->setTileSource(&source);
        QTRY_VERIFY2(m_map->tileStatus().contains(QStringLiteral("offline base map shown")), qPrintable(m_map->tileStatus()));
        QTRY_COMPARE(colourAt(QGeoCoordinate(23, 10)), MapPalette::light().land);
        QCOMPARE(m_map->attribution(), QStringLiteral("Land outlines: Natural Earth"));
    }
};

QTEST_MAIN(TestMapView)
#include "tst_mapview.moc"
