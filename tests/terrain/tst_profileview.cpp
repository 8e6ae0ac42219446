// The elevation profile view in a real offscreen QML scene: a route that flies into a hill shows
// the hill and a red stretch; hovering reads the clearance; clicking a leg selects its waypoint.
#include "ElevationProfileView.h"
#include "ElevationService.h"
#include "RouteDocument.h"
#include "RouteEditor.h"
#include "QuickScene.h"
#include "RouteModel.h"
#include "TerrainProfileModel.h"

#include <QDir>
#include <QItemSelectionModel>
#include <QSignalSpy>
#include <QScopeGuard>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <cmath>
#include <functional>

// Moves a waypoint of the model in place, as an edit of the route does (the profile sees a change of row).
[[maybe_unused]] static void moveWaypointIn(sortie::mission::RouteModel &model, int row, sortie::mission::GeoPoint to)
{
    sortie::mission::Segment s = model.segment(row);
    sortie::mission::asWaypoint(s)->position = to;
    model.replaceSegments({row}, {s});
}

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;
using namespace sortie::terrain;

namespace {
const QByteArray kScene = R"(
import QtQuick
import QtQml.Models
import Sortie.Ui
Item {
    property AbstractItemModel routeModel
    property ItemSelectionModel selection
    property ElevationService elevation
    TerrainProfilePanel {
        objectName: "panel"
        anchors.fill: parent
        routeModel: parent.routeModel
        selectionModel: parent.selection
        elevation: parent.elevation
    }
}
)";

// The waypoint table with a terrain profile beside it, as the route panel places them.
const QByteArray kTableScene = R"(
import QtQuick
import Sortie.Ui
Item {
    id: root
    property RouteDocument doc
    property AbstractItemModel routeModel
    property ElevationService elevation
    TerrainProfileModel {
        id: terrain
        routeModel: root.routeModel
        service: root.elevation
    }
    DisplayUnits { id: units }
    WaypointTable {
        anchors.fill: parent
        doc: root.doc
        routeModel: root.routeModel
        terrain: terrain
        units: units
        theme: Theme {}
    }
}
)";

QQuickItem *findItem(QQuickItem *root, const QString &name)
{
    if (root->objectName() == name)
        return root;
    for (QQuickItem *child : root->childItems())
        if (QQuickItem *found = findItem(child, name))
            return found;
    return nullptr;
}

class HillSource : public ElevationSource
{
public:
    QString name() const override { return QStringLiteral("test hill"); }
    ElevationSample sample(const GeoPoint &p) override
    {
        // 10 m plain, a 100 m hill at 24.005 E; no data east of 24.018 E.
        if (p.longitude > 24.018)
            return ElevationSample::noData();
        const double d = (p.longitude - 24.005) / 0.0015;
        return ElevationSample::value(10 + 100 * std::exp(-d * d));
    }
};

// Keys as the operator types them (QTest::keyClicks takes widgets only).
void typeInto(QWindow *window, const QString &text)
{
    for (const QChar c : text)
        QTest::keyClick(window, c.toLatin1());
}

mission::Route threeWaypoints()
{
    mission::Route r;
    for (double lon : {24.0, 24.01, 24.02}) {
        mission::Waypoint w;
        w.position = {56.9, lon};
        w.altitude = 60;
        w.altitudeType = mission::AltitudeType::Amsl;
        r.segments.push_back(w);
    }
    return r;
}

int countNear(const QImage &image, int x0, int x1, const QColor &colour, int tolerance = 40)
{
    int n = 0;
    for (int x = std::max(0, x0); x <= std::min(image.width() - 1, x1); ++x)
        for (int y = 0; y < image.height(); ++y)
            n += test::colourDistance(image.pixel(x, y), colour.rgb()) < tolerance ? 1 : 0;
    return n;
}

// The topmost pixel of the ground colour in a column.
int groundTop(const QImage &image, int x)
{
    for (int y = 0; y < image.height(); ++y)
        if (test::colourDistance(image.pixel(x, y), QColor(0x8d, 0x6e, 0x63).rgb()) < 30)
            return y;
    return image.height();
}
} // namespace

class TstProfileView : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void hillRedStretchAndClick()
    {
        HillSource hill;
        ElevationService service;
        service.setSources({&hill});
        mission::RouteModel model;
        model.resetRoute(threeWaypoints());
        QItemSelectionModel selection(&model);
        test::QuickScene scene(kScene, QSize(900, 220),
                               {{QStringLiteral("routeModel"), QVariant::fromValue<QObject *>(&model)},
                                {QStringLiteral("selection"), QVariant::fromValue<QObject *>(&selection)},
                                {QStringLiteral("elevation"), QVariant::fromValue<QObject *>(&service)}});
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *view = scene.find<ui::ElevationProfileView>(QStringLiteral("elevationProfile"));
        QVERIFY(view);
        QTRY_VERIFY(view->model() && view->model()->sampleCount() > 10);
        ui::TerrainProfileModel *profile = view->model();
        QCOMPARE(profile->lowStretchCount(), 1);
        QCOMPARE(profile->noDataCount(), 1);
        QVERIFY(profile->sourceText().contains(QStringLiteral("test hill")));

        const auto &p = profile->profile();
        const double hillDistance = p.path.vertexDistance[1] / 2;  // 24.005 E: the middle of leg 1
        const int hillX = int(view->mapToScene({view->xOf(hillDistance), 0}).x());
        const int flatX = int(view->mapToScene({view->xOf(p.path.vertexDistance[1] * 0.1), 0}).x());
        const int leg2X = int(view->mapToScene({view->xOf(p.path.vertexDistance[1] * 1.3), 0}).x());
        QTRY_VERIFY(!scene.grab().isNull());
        const QImage image = scene.grab();
        image.save(QDir::temp().filePath(QStringLiteral("sortie-profile-view.png")));
        // The hill stands out of the plain.
        QVERIFY2(groundTop(image, hillX) + 40 < groundTop(image, flatX),
                 qPrintable(QStringLiteral("%1 vs %2").arg(groundTop(image, hillX)).arg(groundTop(image, flatX))));
        // Red where the route flies into it, none over the second leg.
        QVERIFY(countNear(image, hillX - 3, hillX + 3, QColor(0xd3, 0x2f, 0x2f)) > 4);
        QCOMPARE(countNear(image, leg2X - 3, leg2X + 3, QColor(0xd3, 0x2f, 0x2f)), 0);
        QVERIFY(countNear(image, leg2X - 3, leg2X + 3, QColor(0x15, 0x65, 0xc0)) > 2);  // the route line, blue

        // Hovering reads the point under the mouse.
        QTest::mouseMove(&scene.view(), QPoint(hillX, 100));
        QTRY_VERIFY(view->readout().startsWith(QStringLiteral("Leg 1 ·")));
        QVERIFY(view->readout().contains(QStringLiteral("clearance -")));
        QCOMPARE(view->hoveredLeg(), 0);

        // Clicking selects the leg's first waypoint.
        QSignalSpy clicked(view, &ui::ElevationProfileView::legClicked);
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, QPoint(leg2X, 100));
        QCOMPARE(clicked.count(), 1);
        QCOMPARE(clicked.at(0).at(0).toInt(), 1);
        QCOMPARE(selection.currentIndex().row(), 1);
        QCOMPARE(selection.selectedRows().size(), 1);
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, QPoint(hillX, 100));
        QCOMPARE(selection.currentIndex().row(), 0);
    }

    // The table shows the ground under each waypoint and every altitude as AMSL or AGL, converted
    // through the terrain; a converted cell edits the waypoint in its own type; no data stays blank.
    void tableShowsGroundAndHeights()
    {
        HillSource hill;
        ElevationService service;
        service.setSources({&hill});
        client::RouteDocument doc;
        doc.editor()->setGroundLookup([&service](const mission::GeoPoint &p) { return service.groundAt(p); });
        mission::Route route;
        auto add = [&route](double lon, double altitude, mission::AltitudeType type) {
            mission::Waypoint w;
            w.position = {56.9, lon};
            w.altitude = altitude;
            w.altitudeType = type;
            route.segments.push_back(w);
        };
        add(24.005, 150, mission::AltitudeType::Amsl);  // the hill top: 110 m ground
        add(24.0, 50, mission::AltitudeType::Agl);      // the plain: 10 m
        add(24.02, 60, mission::AltitudeType::Agl);     // no data there
        doc.load(route);
        test::QuickScene scene(kTableScene, QSize(700, 300),
                               {{QStringLiteral("doc"), QVariant::fromValue<QObject *>(&doc)},
                                {QStringLiteral("routeModel"), QVariant::fromValue<QObject *>(doc.model())},
                                {QStringLiteral("elevation"), QVariant::fromValue<QObject *>(&service)}});
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        QQuickItem *root = scene.root();
        auto text = [root](const QString &name) {
            QQuickItem *item = findItem(root, name);
            return item ? item->property("text").toString() : QStringLiteral("<none>");
        };
        QTRY_COMPARE(text(QStringLiteral("groundCell_0")), QStringLiteral("110.0"));
        QCOMPARE(text(QStringLiteral("groundCell_1")), QStringLiteral("10.0"));
        QCOMPARE(text(QStringLiteral("groundCell_2")), QStringLiteral("—"));  // missing, never 0
        auto *terrain = root->findChild<ui::TerrainProfileModel *>();
        QVERIFY(terrain);
        QVERIFY(terrain->groundToolTipOfRow(0).contains(QStringLiteral("EGM96")));
        QVERIFY(terrain->groundToolTipOfRow(0).contains(QStringLiteral("test hill")));
        QVERIFY(terrain->groundToolTipOfRow(2).startsWith(QStringLiteral("No terrain data under this waypoint")));
        // As set: each row's own number.
        QCOMPARE(text(QStringLiteral("altitudeCell_0")), QStringLiteral("150.0"));
        QCOMPARE(text(QStringLiteral("altitudeCell_1")), QStringLiteral("50.0"));

        // The headers stand over their columns, left to right, also once the height frame rewords one.
        const auto headersInARow = [root] {
            double right = -1;
            for (int column = 0; column < 8; ++column) {
                QQuickItem *header = findItem(root, QStringLiteral("waypointHeader_%1").arg(column));
                if (!header || header->x() <= right)
                    return false;
                right = header->x() + header->width() - 1;
            }
            return true;
        };
        QTRY_VERIFY(headersInARow());
        QQuickItem *picker = findItem(root, QStringLiteral("heightsShown"));
        QVERIFY(picker);
        picker->setProperty("currentIndex", 2);  // all AGL
        QTRY_COMPARE(text(QStringLiteral("altitudeCell_0")), QStringLiteral("40.0"));
        QCOMPARE(findItem(root, QStringLiteral("waypointHeader_3"))->property("text").toString(), QStringLiteral("AGL"));
        QTRY_VERIFY(headersInARow());
        QCOMPARE(text(QStringLiteral("altitudeCell_1")), QStringLiteral("50.0"));
        QCOMPARE(text(QStringLiteral("altitudeCell_2")), QStringLiteral("60.0"));
        picker->setProperty("currentIndex", 1);  // all AMSL
        QTRY_COMPARE(text(QStringLiteral("altitudeCell_1")), QStringLiteral("60.0"));
        QCOMPARE(text(QStringLiteral("altitudeCell_2")), QString());  // AGL over no data: unknown
        QVERIFY(findItem(root, QStringLiteral("altitudeCell_2"))->property("readOnly").toBool());

        // 80 m AMSL typed at the AGL waypoint on the plain: it stays AGL, 70 m above the ground.
        QQuickItem *cell = findItem(root, QStringLiteral("altitudeCell_1"));
        cell->setProperty("text", QStringLiteral("80"));
        QMetaObject::invokeMethod(cell, "editingFinished");
        const auto waypoint = [&doc](int row) { return *mission::asWaypoint(doc.model()->segment(row)); };
        QCOMPARE(waypoint(1).altitudeType, mission::AltitudeType::Agl);
        QVERIFY2(std::abs(waypoint(1).altitude - 70.0) < 0.01, qPrintable(QString::number(waypoint(1).altitude)));
        QTRY_COMPARE(text(QStringLiteral("altitudeCell_1")), QStringLiteral("80.0"));
        // And 50 m AGL typed at the AMSL hill-top waypoint: 160 m AMSL.
        picker->setProperty("currentIndex", 2);
        QTRY_COMPARE(text(QStringLiteral("altitudeCell_0")), QStringLiteral("40.0"));
        cell = findItem(root, QStringLiteral("altitudeCell_0"));
        cell->setProperty("text", QStringLiteral("50"));
        QMetaObject::invokeMethod(cell, "editingFinished");
        QCOMPARE(waypoint(0).altitudeType, mission::AltitudeType::Amsl);
        QVERIFY(std::abs(waypoint(0).altitude - 160.0) < 0.01);
        doc.undo();
        QCOMPARE(waypoint(0).altitude, 150.0);
    }

    // In German the table shows "40,0" and takes "40,5" (and a pasted "41.5"); text that is no number
    // is refused where it was typed, red with the reason, and the waypoint keeps its height.
    void numbersInTheLanguagesFormat()
    {
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany)); // what Translations does for German
        const auto restore = qScopeGuard([] { QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates)); });
        HillSource hill;
        ElevationService service;
        service.setSources({&hill});
        client::RouteDocument doc;
        doc.load(threeWaypoints());
        test::QuickScene scene(kTableScene, QSize(700, 300),
                               {{QStringLiteral("doc"), QVariant::fromValue<QObject *>(&doc)},
                                {QStringLiteral("routeModel"), QVariant::fromValue<QObject *>(doc.model())},
                                {QStringLiteral("elevation"), QVariant::fromValue<QObject *>(&service)}});
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        QQuickItem *root = scene.root();
        const auto waypoint = [&doc](int row) { return *mission::asWaypoint(doc.model()->segment(row)); };
        QQuickItem *cell = findItem(root, QStringLiteral("altitudeCell_0"));
        QVERIFY(cell);
        const double before = waypoint(0).altitude;
        QCOMPARE(cell->property("text").toString(), QLocale().toString(before, 'f', 1));
        QVERIFY(cell->property("text").toString().contains(QLatin1Char(',')));
        // Typed as a German operator types it, through the keyboard.
        cell->forceActiveFocus();
        QMetaObject::invokeMethod(cell, "selectAll");
        typeInto(&scene.view(), QStringLiteral("40,5"));
        QTest::keyClick(&scene.view(), Qt::Key_Return);
        QCOMPARE(waypoint(0).altitude, 40.5);
        QTRY_COMPARE(cell->property("text").toString(), QStringLiteral("40,5"));
        QVERIFY(!cell->property("refused").toBool());
        // With a dot, as pasted from elsewhere.
        QMetaObject::invokeMethod(cell, "selectAll");
        typeInto(&scene.view(), QStringLiteral("41.5"));
        QTest::keyClick(&scene.view(), Qt::Key_Return);
        QCOMPARE(waypoint(0).altitude, 41.5);
        // A letter O for a zero: refused, said, nothing changed.
        QMetaObject::invokeMethod(cell, "selectAll");
        typeInto(&scene.view(), QStringLiteral("4O"));
        QTest::keyClick(&scene.view(), Qt::Key_Return);
        QCOMPARE(waypoint(0).altitude, 41.5);
        QVERIFY(cell->property("refused").toBool());
        QCOMPARE(cell->property("text").toString(), QStringLiteral("4O"));  // what was typed stays, to be corrected
        QVERIFY2(cell->property("reason").toString().contains(QStringLiteral("12,5")), qPrintable(cell->property("reason").toString()));
        QTest::keyClick(&scene.view(), Qt::Key_Backspace);  // the next keystroke clears the refusal
        QVERIFY(!cell->property("refused").toBool());
        // The bulk height takes German too; its Set button waits for a number.
        doc.clickRow(1, 0);
        QQuickItem *bulk = findItem(root, QStringLiteral("bulkAltitude"));
        QQuickItem *set = findItem(root, QStringLiteral("bulkAltitudeButton"));
        QVERIFY(bulk && set);
        bulk->setProperty("text", QStringLiteral("zwölf"));
        QVERIFY(!set->isEnabled());
        bulk->setProperty("text", QStringLiteral("12,25"));
        QTRY_VERIFY(set->isEnabled());
        QMetaObject::invokeMethod(set, "clicked");
        QCOMPARE(waypoint(1).altitude, 12.25);
    }

    // Edits are coalesced: a burst of moves costs one recomputation.
    void dragIsCoalesced()
    {
        HillSource hill;
        ElevationService service;
        service.setSources({&hill});
        mission::RouteModel model;
        model.resetRoute(threeWaypoints());
        ui::TerrainProfileModel profile;
        profile.setService(&service);
        profile.setRouteModel(&model);
        profile.recomputeNow();
        const int before = profile.recomputeCount();
        for (int i = 0; i < 50; ++i)
            moveWaypointIn(model, 1, {56.9 + i * 1e-5, 24.01});
        QSignalSpy changed(&profile, &ui::TerrainProfileModel::profileChanged);
        QVERIFY(changed.wait(2000));
        QCOMPARE(profile.recomputeCount(), before + 1);
        QCOMPARE(profile.profile().path.vertices[1].latitude, 56.9 + 49 * 1e-5);
    }
};

QTEST_MAIN(TstProfileView)
#include "tst_profileview.moc"
