// The map draws only when something on it changed (docs/ui.md, "When the map repaints"): a vehicle
// row read again with the same values asks for no picture, a hidden layer asks for none however its
// rows change (and shows the latest when it appears), and several changes between two frames are
// drawn once. Counted through MapLayer's test hooks (pictures asked for, pictures drawn) in a real
// offscreen scene; no timing.
#include "MapView.h"
#include "QuickScene.h"
#include "VehicleLayer.h"
#include "WebMercator.h"

#include <QStandardItemModel>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie::ui;
using sortie::test::QuickScene;

namespace {

const QByteArray kScene = R"(
import QtQuick
import Sortie.Ui
Item {
    MapView { id: map; objectName: "map"; anchors.fill: parent; latitude: 56.95; longitude: 24.1; zoomLevel: 14 }
    Item {
        objectName: "page" // as a StackLayout hides a page not shown
        anchors.fill: parent
        VehicleLayer { objectName: "vehicles"; anchors.fill: parent; map: map }
    }
}
)";

enum Role { IdRole = Qt::UserRole + 1, NameRole, LatRole, LonRole, HeadingRole, StaleRole, BatteryRole };

} // namespace

class TestIdleRepaint : public QObject
{
    Q_OBJECT

    std::unique_ptr<QuickScene> m_scene;
    VehicleLayer *m_layer = nullptr;
    QQuickItem *m_page = nullptr;
    QStandardItemModel *m_model = nullptr;

    // Puts a row's values (all of them, as a fleet's dataChanged does) into the model.
    void report(int row, double latitude, double longitude, double heading, double battery)
    {
        QStandardItem *item = m_model->item(row);
        item->setData(latitude, LatRole);
        item->setData(longitude, LonRole);
        item->setData(heading, HeadingRole);
        item->setData(battery, BatteryRole); // a role the layer does not draw
        // QStandardItem signals only a real change: this is the fleet's "row changed" for every role.
        emit m_model->dataChanged(m_model->index(row, 0), m_model->index(row, 0));
    }
    // Renders a frame (polish, paint what asked, composite) as the window would.
    void frame() { m_scene->grab(); }

private slots:
    void initTestCase() { sortie::test::useSoftwareRendering(); }

    void init()
    {
        m_scene = std::make_unique<QuickScene>(kScene, QSize(800, 600));
        QVERIFY2(m_scene->isReady(), qPrintable(m_scene->errors()));
        m_layer = m_scene->find<VehicleLayer>(QStringLiteral("vehicles"));
        m_page = m_scene->find<QQuickItem>(QStringLiteral("page"));
        QVERIFY(m_layer && m_page);
        m_model = new QStandardItemModel(m_scene->root());
        m_model->setItemRoleNames({{IdRole, "vehicleId"}, {NameRole, "name"}, {LatRole, "latitude"}, {LonRole, "longitude"},
                                   {HeadingRole, "heading"}, {StaleRole, "stale"}, {BatteryRole, "battery"}});
        for (int row = 0; row < 3; ++row) {
            auto *item = new QStandardItem;
            item->setData(QStringLiteral("EMU-10%1").arg(row + 1), IdRole);
            item->setData(QStringLiteral("EMU-10%1").arg(row + 1), NameRole);
            item->setData(56.95 + 0.002 * row, LatRole);
            item->setData(24.1, LonRole);
            item->setData(90.0, HeadingRole);
            item->setData(false, StaleRole);
            item->setData(80.0, BatteryRole);
            m_model->appendRow(item);
        }
        m_layer->setModel(m_model);
        frame();
        QCOMPARE(m_layer->positionedCount(), 3);
        QVERIFY(m_layer->paintCount() > 0);
    }

    void cleanup() { m_scene.reset(); }

    // Three parked vehicles repeating their telemetry: not one picture asked for, none drawn.
    void parkedVehiclesRepeatingThemselvesDrawNothing()
    {
        const int asked = m_layer->repaintRequests();
        const int drawn = m_layer->paintCount();
        for (int tick = 0; tick < 50; ++tick) {
            for (int row = 0; row < 3; ++row)
                report(row, 56.95 + 0.002 * row, 24.1, 90.0, 80.0);
            frame();
        }
        QCOMPARE(m_layer->repaintRequests(), asked);
        QCOMPARE(m_layer->paintCount(), drawn);
        // A value the layer does not draw (the battery) changes the row, not the picture.
        report(0, 56.95, 24.1, 90.0, 79.0);
        frame();
        QCOMPARE(m_layer->repaintRequests(), asked);
        QCOMPARE(m_layer->paintCount(), drawn);
        // A real move is drawn.
        const QPointF before = m_layer->vehiclePosition(0);
        report(0, 56.951, 24.1, 90.0, 79.0);
        frame();
        QCOMPARE(m_layer->paintCount(), drawn + 1);
        QVERIFY(m_layer->vehiclePosition(0) != before);
    }

    // Moves of three vehicles between two frames: one picture.
    void changesBetweenFramesAreDrawnOnce()
    {
        const int drawn = m_layer->paintCount();
        for (int row = 0; row < 3; ++row)
            report(row, 56.951 + 0.002 * row, 24.101, 45.0, 80.0);
        report(1, 56.9535, 24.102, 30.0, 80.0);
        frame();
        QCOMPARE(m_layer->paintCount(), drawn + 1);
        frame(); // nothing new: nothing drawn
        QCOMPARE(m_layer->paintCount(), drawn + 1);
    }

    // A layer on a page not shown asks for no frame while its vehicles move; shown, it draws them
    // where they are now.
    void aHiddenLayerAsksForNothing()
    {
        m_page->setVisible(false);
        frame();
        const int asked = m_layer->repaintRequests();
        const int drawn = m_layer->paintCount();
        for (int tick = 1; tick <= 20; ++tick) {
            report(0, 56.95 + 0.0001 * tick, 24.1, 90.0 + tick, 80.0);
            frame();
        }
        QCOMPARE(m_layer->repaintRequests(), asked);
        QCOMPARE(m_layer->paintCount(), drawn);
        m_page->setVisible(true);
        frame();
        QCOMPARE(m_layer->paintCount(), drawn + 1);
        const QPointF expected = m_scene->find<MapView>(QStringLiteral("map"))->viewport().toScreen(
            WebMercator::project(QGeoCoordinate(56.95 + 0.002, 24.1)));
        QVERIFY(std::abs(m_layer->vehiclePosition(0).y() - expected.y()) < 1.0); // its last position
    }
};

QTEST_MAIN(TestIdleRepaint)
#include "tst_idlerepaint.moc"
