// Will the battery last, on the mission page, offscreen with the program's own wiring: a route too
// long for one battery under the operator's energy profile shows its energy and "N batteries" in
// the route panel, an error in the validation list, and on the map (and in the terrain profile) the
// battery change it needs and its point of no return, drawn where RouteEndurance puts them.
#include "ClientWindow.h"
#include "MapPalette.h"
#include "ElevationProfileView.h"
#include "EnduranceLayer.h"
#include "QuickScene.h"
#include "Route.h"
#include "RouteLayer.h"
#include "RouteAnalyzer.h"
#include "RouteDocument.h"
#include "RouteEndurance.h"

#include <QDir>
#include <QFile>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

// A 2 km square flown twice at 10 m/s, 60 m up, from a home at its south-west corner: about 16 km.
mission::Route longSquare()
{
    mission::Route route;
    route.settings.name = QStringLiteral("Long square");
    route.settings.home = mission::HomePosition{{56.9400, 24.0800}, 12.0};
    const double dLat = 2000.0 / 111320.0, dLon = 2000.0 / (111320.0 * std::cos(56.95 * M_PI / 180.0));
    const std::pair<double, double> corners[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    for (size_t i = 0; i < std::size(corners); ++i) {
        mission::Waypoint w;
        w.position = {56.9400 + corners[i].first * dLat, 24.0800 + corners[i].second * dLon};
        w.altitude = 60;
        w.speed = 10;
        w.role = i == 0 ? mission::WaypointRole::Takeoff : i + 1 == std::size(corners) ? mission::WaypointRole::Land : mission::WaypointRole::Pass;
        route.segments.push_back(w);
    }
    return route;
}

bool nearColour(const QImage &image, QPointF at, const QColor &colour, int radius = 4)
{
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const QPoint p = (at + QPointF(dx, dy)).toPoint();
            if (!image.rect().contains(p))
                continue;
            const QColor c = image.pixelColor(p);
            if (std::abs(c.red() - colour.red()) < 24 && std::abs(c.green() - colour.green()) < 24 && std::abs(c.blue() - colour.blue()) < 24)
                return true;
        }
    return false;
}

} // namespace

class TestEnduranceView : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void aRouteTooLongForOneBatteryIsShownAsSuch()
    {
        test::ClientWindow app;
        QVERIFY2(app.isReady(), qPrintable(app.error()));
        app.showPage(1);
        client::RouteDocument *doc = app.missions().document();
        doc->load(longSquare());
        auto *routeLayer = app.find<ui::RouteLayer>(QStringLiteral("routeLayer"));
        QVERIFY(routeLayer);
        QTRY_COMPARE(routeLayer->count(), 9);
        QTRY_VERIFY(routeLayer->width() > 400);
        routeLayer->fitToMap(60);

        // Without a profile nothing is guessed: the panel says what is missing.
        endurance::RouteEndurance &endurance = app.graph().endurance();
        QVERIFY(endurance.isMissing());
        auto *problem = app.find<QQuickItem>(QStringLiteral("enduranceProblem"));
        QVERIFY(problem);
        QTRY_VERIFY(problem->isVisible());
        QVERIFY(problem->property("text").toString().contains(QStringLiteral("energy profile")));
        auto *layer = app.find<ui::EnduranceLayer>(QStringLiteral("enduranceLayer"));
        QVERIFY(layer);
        QCOMPARE(layer->markCount(), 0);

        // A 60 Wh battery (48 usable) against about 16 km at 10 m/s and 260 W: about 115 Wh.
        QTemporaryDir dir;
        const QString profile = QDir(dir.path()).filePath(QStringLiteral("quad.json"));
        QFile file(profile);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"name": "Test quad", "batteryWh": 60, "cruiseSpeed": 10, "climbRate": 3, "descentRate": 2,
                      "hoverPowerW": 300, "cruisePowerW": 260, "climbPowerW": 420, "descentPowerW": 210})");
        file.close();
        QVERIFY(endurance.loadProfile(profile));
        QTRY_VERIFY(!endurance.isMissing());
        const int batteries = endurance.batteriesNeeded().toInt();
        QVERIFY2(batteries >= 2, qPrintable(QString::number(batteries)));

        const auto text = [&app](const char *name) { return app.find<QQuickItem>(QString::fromLatin1(name))->property("text").toString(); };
        QTRY_COMPARE(text("enduranceAtEnd"), QStringLiteral("%1 batteries").arg(batteries));
        QCOMPARE(text("enduranceEnergy"), QStringLiteral("%1 Wh").arg(endurance.energyWh().toDouble(), 0, 'f', 0));
        QCOMPARE(text("enduranceProfile"), QStringLiteral("Test quad (file)"));
        QVERIFY2(text("enduranceNoReturn").startsWith(QStringLiteral("after ")), qPrintable(text("enduranceNoReturn")));
        QVERIFY(!problem->isVisible());

        // The validation says the change is not planned, and the upload gate would refuse it.
        QTRY_VERIFY(doc->analyzer()->validation().errorCount() > 0);

        // On the map: each change (amber: not planned) and the point of no return (red).
        const int changes = endurance.changeCount();
        QCOMPARE(changes, batteries - 1);
        QTRY_COMPARE(layer->markCount(), changes + 1);
        QVERIFY(test::waitForFrame(app.window()));
        const QImage image = app.window()->grabWindow();
        const auto inWindow = [layer](int i) { return layer->mapToScene(layer->markPosition(i)); };
        QVERIFY2(nearColour(image, inWindow(changes), ui::MapPalette::light().noReturn), "no red diamond at the point of no return");
        // The battery glyph stands above its point.
        QVERIFY2(nearColour(image, inWindow(0) + QPointF(0, -21), ui::MapPalette::light().unplanned), "no amber battery at the change");

        // In the terrain profile too, at the same places along the path.
        auto *profileView = app.find<ui::ElevationProfileView>(QStringLiteral("elevationProfile"));
        QVERIFY(profileView);
        QTRY_COMPARE(profileView->markerCount(), changes + 1);
        // The route passes its corners twice: each mark is where its own distance says, not the
        // first pass by the same place.
        std::vector<double> places;
        for (const endurance::BatteryChange &change : endurance.estimate()->changes)
            places.push_back(change.at.distance);
        QVERIFY2(endurance.noReturnDistance().isValid(), "the route has a point of no return: a missing one must not read as 0 m");
        places.push_back(endurance.noReturnDistance().toDouble());
        for (int i = 0; i <= changes; ++i) {
            const double distance = places[size_t(i)];
            QTRY_VERIFY(std::isfinite(profileView->markerDistance(i)));
            QVERIFY2(std::abs(profileView->markerDistance(i) - distance) < 1,
                     qPrintable(QStringLiteral("%1 vs %2").arg(profileView->markerDistance(i)).arg(distance)));
        }
        QVERIFY(places[size_t(changes - 1)] > 8000); // the second lap

        if (qEnvironmentVariableIsSet("SORTIE_SCREENSHOT_DIR"))
            image.save(QDir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR")).filePath(QStringLiteral("endurance.png")));
        image.save(QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR "/endurance.png"));
    }
};

QTEST_MAIN(TestEnduranceView)
#include "tst_enduranceview.moc"
