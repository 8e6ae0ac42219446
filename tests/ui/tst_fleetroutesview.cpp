// Every route on one map, offscreen with the program's own wiring against the embedded simulator:
// two emulator vehicles get routes (uploaded as the mission view's Upload does), a third route is
// open and planned for a third vehicle. The mission view draws the two uploaded routes in their
// vehicles' colours under the open one, the fly view draws all three, and both list them beside
// the map with vehicle, state and times. Screenshots of both views go to SORTIE_SCREENSHOT_DIR.
#include "ClientWindow.h"
#include "FleetRoutes.h"
#include "FleetRoutesLayer.h"
#include "MapView.h"
#include "MissionUploader.h"
#include "QuickScene.h"
#include "RouteDocument.h"
#include "RouteLayer.h"
#include "RoutePreparation.h"
#include "VehiclePalette.h"
#include "VisualCheck.h"

#include <QDir>
#include <QSignalSpy>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

// Four waypoints on a square whose near corner is `north` m north and `east` m east of `at`.
mission::Route squareNear(const QGeoCoordinate &at, double north, double east, const QString &name)
{
    mission::Route route;
    route.settings.name = name;
    const QGeoCoordinate corner = at.atDistanceAndAzimuth(north, 0).atDistanceAndAzimuth(east, 90);
    for (const auto &[n, e] : {std::pair{0.0, 0.0}, {150.0, 0.0}, {150.0, 150.0}, {0.0, 150.0}}) {
        const QGeoCoordinate p = corner.atDistanceAndAzimuth(n, 0).atDistanceAndAzimuth(e, 90);
        mission::Waypoint w;
        w.position = {p.latitude(), p.longitude()};
        w.altitude = 30;
        w.speed = 8;
        route.segments.push_back(w);
    }
    return route;
}

QString screenshotPath(const QString &name)
{
    const QDir dir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR)));
    dir.mkpath(QStringLiteral("."));
    return dir.filePath(name);
}

// Pixels of `colour` (within a small distance) in a box around a point.
int pixelsNear(const QImage &image, QPointF at, const QColor &colour, int radius = 5)
{
    int n = 0;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const QPoint p = (at + QPointF(dx, dy)).toPoint();
            n += image.rect().contains(p) && test::colourDistance(image.pixel(p), colour.rgb()) < 40;
        }
    return n;
}

} // namespace

class TestFleetRoutesView : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_client;
    std::vector<mission::Route> m_routes;

    vehicle::Vehicle *emu(const QString &name) const
    {
        for (int row = 0; row < m_client->fleet().count(); ++row) {
            vehicle::Vehicle *v = m_client->fleet().vehicleAt(row);
            if (v->name() == name && v->position().isValid())
                return v;
        }
        return nullptr;
    }
    int fleetRow(const vehicle::Vehicle *v) const
    {
        for (int row = 0; row < m_client->fleet().count(); ++row) {
            if (m_client->fleet().vehicleAt(row) == v)
                return row;
        }
        return -1;
    }
    static QString idOf(const vehicle::Vehicle *v) { return v->protocol() + QLatin1Char(':') + v->id(); }
    // Opens `route`, chooses `v` for it; uploads it unless only planning.
    void give(const mission::Route &route, vehicle::Vehicle *v, bool upload)
    {
        client::RoutePreparation *preparation = m_client->missions().preparation();
        m_client->missions().document()->load(route);
        preparation->setVehicleId(idOf(v));
        if (!upload)
            return;
        client::MissionUploader *uploader = preparation->uploader();
        QSignalSpy finished(uploader, &client::MissionUploader::finished);
        preparation->upload();
        QTRY_VERIFY_WITH_TIMEOUT(!finished.isEmpty() || uploader->isAsking(), 15000);
        if (uploader->isAsking())
            uploader->confirm();
        QTRY_VERIFY_WITH_TIMEOUT(!finished.isEmpty(), 15000);
        QVERIFY2(uploader->state() == client::MissionUploader::State::Done, qPrintable(uploader->message()));
    }
    // Frames every route on a page's map.
    void frameRoutes(const char *page)
    {
        double south = 90, west = 180, north = -90, east = -180;
        for (const QString &name : {QStringLiteral("EMU-101"), QStringLiteral("EMU-102"), QStringLiteral("EMU-103")}) {
            const QGeoCoordinate p = emu(name)->position();
            south = std::min(south, p.latitude());
            north = std::max(north, p.latitude());
            west = std::min(west, p.longitude());
            east = std::max(east, p.longitude());
        }
        for (const mission::Route &route : m_routes)
            for (const mission::Segment &s : route.segments) {
                const auto &w = std::get<mission::Waypoint>(s);
                south = std::min(south, w.position.latitude);
                north = std::max(north, w.position.latitude);
                west = std::min(west, w.position.longitude);
                east = std::max(east, w.position.longitude);
            }
        auto *map = m_client->page(page)->property("map").value<ui::MapView *>();
        QTRY_VERIFY(map->width() > 300);
        map->fitBounds(south, west, north, east, 60);
    }
    // The list's rows beside a page's map: route name, state and times of each, as laid out.
    QStringList listRows(const QString &list)
    {
        auto *view = m_client->find(list)->findChild<QQuickItem *>(QStringLiteral("fleetRoutesView"));
        QStringList rows;
        for (int row = 0; row < m_client->graph().fleetRoutes()->count(); ++row) {
            QQuickItem *delegate = nullptr;
            QMetaObject::invokeMethod(view, "itemAtIndex", Q_RETURN_ARG(QQuickItem *, delegate), Q_ARG(int, row));
            if (!delegate || !delegate->isVisible())
                continue;
            QStringList texts;
            for (const char *name : {"routeName", "routeVehicle", "routeState", "routeTimes"})
                texts << delegate->findChild<QObject *>(QString::fromLatin1(name))->property("text").toString();
            // Nothing cut short: every line of the row shows all of its text.
            for (const char *name : {"routeName", "routeState"}) {
                auto *label = delegate->findChild<QQuickItem *>(QString::fromLatin1(name));
                if (label->property("truncated").toBool())
                    rows << QStringLiteral("truncated: %1").arg(label->property("text").toString());
            }
            rows << texts.join(QStringLiteral(" | "));
        }
        return rows;
    }
    // The page's texts (the list's among them): none clipped, out of the window or over another.
    void noTextProblems(const char *page)
    {
        QVERIFY(test::waitForFrame(m_client->window()));
        const QStringList problems = test::inspectTexts(qobject_cast<QQuickItem *>(m_client->page(page)));
        QVERIFY(test::lastInspectedTextCount() > 10);
        QVERIFY2(problems.isEmpty(), qPrintable(QString::fromLatin1(page) + QStringLiteral(":\n  ") + problems.join(QStringLiteral("\n  "))));
    }
    void shoot(const QString &name)
    {
        QVERIFY(test::waitForFrame(m_client->window()));
        QVERIFY(m_client->window()->grabWindow().save(screenshotPath(name)));
    }

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void everyRouteOnBothMapsAndInTheLists()
    {
        m_client = std::make_unique<test::ClientWindow>();
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
        QVERIFY(m_client->logIn());
        QTRY_VERIFY_WITH_TIMEOUT(emu(QStringLiteral("EMU-101")) && emu(QStringLiteral("EMU-102")) && emu(QStringLiteral("EMU-103")), 10000);
        vehicle::Vehicle *first = emu(QStringLiteral("EMU-101")), *second = emu(QStringLiteral("EMU-102")),
                         *third = emu(QStringLiteral("EMU-103"));
        // Three squares side by side north of the first vehicle, clear of every vehicle's mark.
        const QGeoCoordinate at = first->position();
        m_routes = {squareNear(at, 250, -400, QStringLiteral("West field")), squareNear(at, 250, -75, QStringLiteral("Middle field")),
                    squareNear(at, 250, 250, QStringLiteral("East field"))};
        give(m_routes[0], first, true);
        give(m_routes[1], second, true);
        give(m_routes[2], third, false); // open in the editor, planned for the third vehicle
        client::FleetRoutes *routes = m_client->graph().fleetRoutes();
        QCOMPARE(routes->count(), 3);

        // The mission view: the two uploaded routes in their vehicles' colours; the open one is the editor's.
        m_client->showPage(1);
        frameRoutes("missionPage");
        auto *missionLayer = m_client->find<ui::FleetRoutesLayer>(QStringLiteral("missionFleetRoutesLayer"));
        QVERIFY(missionLayer);
        QTRY_COMPARE(missionLayer->routeCount(), 2);
        QVERIFY(test::waitForFrame(m_client->window()));
        QImage image = m_client->window()->grabWindow();
        for (int row : {0, 1}) {
            const QColor colour = client::vehicleColor(fleetRow(row == 0 ? first : second));
            QCOMPARE(missionLayer->routeColor(row), colour);
            // Halfway along the square's second leg, in window pixels.
            const QPointF mid = (missionLayer->pointPosition(row, 1) + missionLayer->pointPosition(row, 2)) / 2;
            const QPointF inWindow = missionLayer->mapToScene(mid);
            QVERIFY2(pixelsNear(image, inWindow, colour) > 3, qPrintable(QStringLiteral("row %1 at %2,%3").arg(row).arg(inWindow.x()).arg(inWindow.y())));
        }
        QCOMPARE(routes->data(routes->index(0), client::FleetRoutes::ColorRole).value<QColor>(), missionLayer->routeColor(0));
        QVERIFY(missionLayer->routeColor(0) != missionLayer->routeColor(1));
        const QStringList missionRows = listRows(QStringLiteral("missionFleetRoutes"));
        QCOMPARE(missionRows.size(), 3);
        QVERIFY2(missionRows[0].startsWith(QStringLiteral("West field | EMU-101 | uploaded ")), qPrintable(missionRows[0]));
        QVERIFY2(missionRows[1].startsWith(QStringLiteral("Middle field | EMU-102 | uploaded ")), qPrintable(missionRows[1]));
        QVERIFY2(missionRows[2].startsWith(QStringLiteral("East field | EMU-103 | planned | ")), qPrintable(missionRows[2]));
        QVERIFY2(missionRows[2].endsWith(QStringLiteral(" flight")) && !missionRows[2].contains(QStringLiteral("—")), qPrintable(missionRows[2]));
        noTextProblems("missionPage");
        shoot(QStringLiteral("fleet-routes-mission.png"));

        // The second vehicle flies: the fly view draws every route (the planned one too) and its row says how far.
        QSignalSpy commands(second, &vehicle::Vehicle::commandFinished);
        second->arm();
        QTRY_COMPARE(commands.count(), 1);
        second->setMode(QStringLiteral("auto"));
        QTRY_COMPARE_WITH_TIMEOUT(routes->data(routes->index(1), client::FleetRoutes::StateRole).toString(), QStringLiteral("flying"), 15000);
        m_client->showPage(2);
        auto *vehicles = m_client->find<QQuickItem>(QStringLiteral("vehicleLayer"));
        vehicles->setProperty("currentIndex", fleetRow(second)); // its routes on top, its row highlighted
        QVERIFY(test::waitForFrame(m_client->window()));
        frameRoutes("telemetryPage");
        auto *flyLayer = m_client->find<ui::FleetRoutesLayer>(QStringLiteral("flyFleetRoutesLayer"));
        QVERIFY(flyLayer);
        QTRY_COMPARE(flyLayer->routeCount(), 3);
        // Framed on the routes: every one of their points is on the map.
        for (int row = 0; row < 3; ++row)
            for (int i = 0; i < 4; ++i)
                QTRY_VERIFY(QRectF(0, 0, flyLayer->width(), flyLayer->height()).contains(flyLayer->pointPosition(row, i)));
        QTRY_COMPARE(listRows(QStringLiteral("flyFleetRoutes")).size(), 3);
        const QStringList flyRows = listRows(QStringLiteral("flyFleetRoutes"));
        QVERIFY2(flyRows[1].contains(QStringLiteral("EMU-102 | flying: waypoint ")), qPrintable(flyRows[1]));
        QVERIFY2(flyRows[1].contains(QStringLiteral(" flown · ")), qPrintable(flyRows[1]));
        // Three routes fit: no scroll bar; the vehicles above the list keep room for their rows.
        auto *flyView = m_client->find(QStringLiteral("flyFleetRoutes"))->findChild<QQuickItem *>(QStringLiteral("fleetRoutesView"));
        QVERIFY2(!flyView->property("overflowing").toBool(), qPrintable(QStringLiteral("%1 in %2").arg(flyView->property("contentHeight").toDouble()).arg(flyView->height())));
        auto *vehicleList = m_client->find(QStringLiteral("vehicleList"));
        QVERIFY2(vehicleList->height() >= 3 * 24, qPrintable(QString::number(vehicleList->height())));
        noTextProblems("telemetryPage");
        shoot(QStringLiteral("fleet-routes-fly.png"));
    }

    void cleanupTestCase() { m_client.reset(); }
};

QTEST_MAIN(TestFleetRoutesView)
#include "tst_fleetroutesview.moc"
