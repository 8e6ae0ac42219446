// The main window offscreen: pages, shortcuts, help overlay, status bar, map source wiring,
// and a PNG of each view (docs/images when SORTIE_SCREENSHOT_DIR points there).
#include "AppSettings.h"
#include "ClientGraph.h"
#include "MissionController.h"
#include "Route.h"
#include "RouteDocument.h"
#include "MapView.h"
#include "PasswordVault.h"
#include "QuickScene.h"
#include "RouteLayer.h"
#include "MainWindow.h"
#include "TileHttpServer.h"
#include "Translations.h"
#include "VehicleLayer.h"

#include <QDir>
#include <QGuiApplication>
#include <QPalette>
#include <QQuickItem>
#include <QQuickWindow>
#include <QSettings>
#include <QStandardItemModel>
#include <QTemporaryDir>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie::ui;

namespace {

enum VehicleRole { IdRole = Qt::UserRole + 1, NameRole, LatRole, LonRole, HeadingRole, HomeLatRole, HomeLonRole };

QString screenshotDir()
{
    const QString dir = qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR));
    QDir().mkpath(dir);
    return dir;
}

// Demonstration content for the pictures: a survey route near Riga (waypoints around an area scan)
// and three vehicles.
sortie::mission::Route surveyRoute()
{
    using namespace sortie::mission;
    Route route;
    const auto waypoint = [&route](double lat, double lon, double altitude) {
        Waypoint w;
        w.position = {lat, lon};
        w.altitude = altitude;
        w.speed = 8;
        route.segments.push_back(w);
    };
    waypoint(56.9468, 24.0850, 0);
    waypoint(56.9500, 24.0950, 60);
    AreaScan scan;
    for (const auto &[lat, lon] : {std::pair{56.9450, 24.0985}, {56.9575, 24.0985}, {56.9575, 24.1165}, {56.9450, 24.1165}})
        scan.polygon.push_back({lat, lon});
    scan.parameters.sideDistanceMeters = 180;
    route.segments.push_back(scan);
    waypoint(56.9580, 24.1250, 60);
    waypoint(56.9520, 24.1320, 60);
    waypoint(56.9440, 24.1180, 40);
    waypoint(56.9420, 24.0900, 0);
    return route;
}

void fillVehicles(QStandardItemModel &vehicles)
{
    vehicles.setItemRoleNames({{IdRole, "vehicleId"}, {NameRole, "name"}, {LatRole, "latitude"}, {LonRole, "longitude"},
                               {HeadingRole, "heading"}, {HomeLatRole, "homeLatitude"}, {HomeLonRole, "homeLongitude"}});
    const struct { const char *name; double lat, lon, heading; } fleet[] = {
        {"EMU-101 (HCI)", 56.9510, 24.1050, 45}, {"EMU-102 (HCI)", 56.9470, 24.1220, 200}, {"VCI sim 1", 56.9555, 24.0900, 300}};
    for (const auto &v : fleet) {
        auto *item = new QStandardItem;
        item->setData(QString::fromLatin1(v.name), IdRole);
        item->setData(QString::fromLatin1(v.name), NameRole);
        item->setData(v.lat - 0.003, LatRole);
        item->setData(v.lon - 0.004, LonRole);
        item->setData(v.heading, HeadingRole);
        item->setData(56.9468, HomeLatRole);
        item->setData(24.0850 + (&v - fleet) * 0.004, HomeLonRole);
        vehicles.appendRow(item);
    }
}

// Flies each vehicle a few steps, so the trails show.
void flyVehicles(QStandardItemModel &vehicles)
{
    for (int step = 1; step <= 12; ++step) {
        for (int row = 0; row < vehicles.rowCount(); ++row) {
            const QModelIndex index = vehicles.index(row, 0);
            vehicles.setItemData(index, {{LatRole, index.data(LatRole).toDouble() + 0.00025},
                                         {LonRole, index.data(LonRole).toDouble() + 0.0003 * std::sin(step * 0.5 + row)}});
        }
    }
}

} // namespace

class TestMainWindow : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    sortie::secrets::PasswordVault m_vault{QStringLiteral("sortie-tests")}; // no keyring under ctest: nothing remembered
    std::unique_ptr<QSettings> m_storage;
    std::unique_ptr<AppSettings> m_settings;
    std::unique_ptr<sortie::client::ClientGraph> m_client; // the program's controllers, not logged in
    std::unique_ptr<sortie::ui::MainWindow> m_mainWindow;
    QQuickWindow *m_window = nullptr;

    template <typename T = QObject>
    T *find(const char *name) const
    {
        return m_window->findChild<T *>(QString::fromLatin1(name));
    }
    QObject *page(const char *name) const { return m_window->property(name).value<QObject *>(); }

    void save(const QString &name, int minimumColours = 12)
    {
        const QImage image = m_window->grabWindow();
        QCOMPARE(image.size(), QSize(1280, 800));
        QVERIFY2(sortie::test::distinctColours(image) >= minimumColours, qPrintable(name + " looks blank"));
        const QString path = QDir(screenshotDir()).filePath(name);
        QVERIFY2(image.save(path), qPrintable(path));
    }

    void verifyShown(const char *name)
    {
        auto *item = find<QQuickItem>(name);
        QVERIFY2(item, name);
        // Pages lay out on the frame after they are shown.
        QTRY_VERIFY2(item->isVisible() && item->width() > 0 && item->height() > 0, name);
        const QRectF inWindow = item->mapRectToScene(QRectF(0, 0, item->width(), item->height()));
        QVERIFY2(QRectF(0, 0, m_window->width(), m_window->height()).intersects(inWindow), name);
    }

private slots:
    void initTestCase()
    {
        sortie::test::useSoftwareRendering();
        // No keyring, even in a desktop session: nothing listens at this session bus address.
        qputenv("DBUS_SESSION_BUS_ADDRESS", "unix:path=/nonexistent/sortie-tst-mainwindow");
    }

    void init()
    {
        m_storage = std::make_unique<QSettings>(m_dir.filePath(QStringLiteral("sortie.ini")), QSettings::IniFormat);
        m_storage->clear();
        m_settings = std::make_unique<AppSettings>(m_storage.get(), &m_vault);
        m_client = std::make_unique<sortie::client::ClientGraph>(m_storage.get(), sortie::client::ClientGraph::Options{});
        m_mainWindow = std::make_unique<sortie::ui::MainWindow>(*m_client, *m_settings);
        QVERIFY2(m_mainWindow->loadWarnings().isEmpty(), qPrintable(m_mainWindow->loadWarnings().join(QLatin1Char('\n'))));
        m_window = m_mainWindow->window();
        QVERIFY(m_window);
        m_window->resize(1280, 800);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
    }

    void cleanup()
    {
        m_mainWindow.reset();
        m_client.reset();
        m_settings.reset();
        m_storage.reset();
        QGuiApplication::setPalette(QPalette());
    }

    void statusBarShowsTheConnectionState()
    {
        auto *label = find<QObject>("connectionStateLabel");
        QVERIFY(label);
        QCOMPARE(label->property("text").toString(), QStringLiteral("Disconnected"));
        m_window->setProperty("connectionState", QStringLiteral("Reconnecting"));
        m_window->setProperty("connectionStateText", QStringLiteral("Reconnecting")); // the controller's words, stood in for
        m_window->setProperty("connectionDetail", QStringLiteral("attempt 2"));
        QCOMPARE(label->property("text").toString(), QStringLiteral("Reconnecting — attempt 2"));
    }

    void shortcutsSwitchPagesAndShowHelp()
    {
        QCOMPARE(m_window->property("currentPage").toInt(), 0);
        QTest::keyClick(m_window, Qt::Key_2, Qt::ControlModifier);
        QCOMPARE(m_window->property("currentPage").toInt(), 1);
        QTest::keyClick(m_window, Qt::Key_3, Qt::ControlModifier);
        QCOMPARE(m_window->property("currentPage").toInt(), 2);
        QTest::keyClick(m_window, Qt::Key_1, Qt::ControlModifier);
        QCOMPARE(m_window->property("currentPage").toInt(), 0);

        QObject *help = m_window->property("helpOverlay").value<QObject *>();
        QVERIFY(help);
        QTest::keyClick(m_window, Qt::Key_F1);
        QTRY_VERIFY(help->property("opened").toBool());
        auto *grid = find<QQuickItem>("shortcutGrid");
        QVERIFY(grid);
        QVERIFY(grid->childItems().size() >= 16); // two labels per shortcut
        QTest::keyClick(m_window, Qt::Key_Escape);
        QTRY_VERIFY(!help->property("opened").toBool());
    }

    // Without a keyring the login view says so beside a disabled "remember" box, and a click on it
    // remembers nothing.
    void rememberNeedsAKeyring()
    {
        QTRY_COMPARE(m_vault.state(), sortie::secrets::PasswordVault::State::Unavailable);
        auto *remember = find<QQuickItem>("rememberCheck");
        auto *notice = find<QQuickItem>("rememberNotice");
        QVERIFY(remember && notice);
        QTRY_VERIFY(notice->isVisible());
        QVERIFY(!remember->isEnabled());
        QVERIFY(!remember->property("checked").toBool());
        const QString text = notice->property("text").toString();
        QVERIFY2(text.startsWith(QStringLiteral("No keyring is reachable, so the password cannot be remembered (")) && text.contains(m_vault.unavailableReason()),
                 qPrintable(text));
        QTest::mouseClick(m_window, Qt::LeftButton, {}, remember->mapToScene(QPointF(10, remember->height() / 2)).toPoint());
        QVERIFY(!remember->property("checked").toBool());
        QVERIFY(!m_settings->rememberPassword());
        QVERIFY(!m_storage->value(QStringLiteral("connection/rememberPassword")).toBool());
    }

    void unitsAndMapSourceFollowTheSettings()
    {
        QTest::keyClick(m_window, Qt::Key_2, Qt::ControlModifier);
        const auto scaleBars = m_window->findChildren<QQuickItem *>(QStringLiteral("scaleBar"));
        QVERIFY(!scaleBars.isEmpty());
        m_settings->setUnits(QStringLiteral("imperial"));
        for (QQuickItem *bar : scaleBars)
            QVERIFY(bar->property("imperial").toBool());

        sortie::test::TileHttpServer server;
        QVERIFY(server.listen());
        const QString urlTemplate = server.urlTemplate();
        server.close();
        m_settings->setTileUrlTemplate(urlTemplate);
        m_settings->setMapSource(QStringLiteral("xyz"));
        auto *map = page("missionPage")->property("map").value<MapView *>();
        QVERIFY(map);
        QVERIFY(map->tileSource());
        QTRY_VERIFY2(map->tileStatus().contains(QStringLiteral("offline base map shown")), qPrintable(map->tileStatus()));
        auto *tileLabel = find<QObject>("tileStatusLabel");
        QTRY_COMPARE(tileLabel->property("text").toString(), map->tileStatus());
        m_settings->setMapSource(QStringLiteral("offline"));
        QVERIFY(!map->tileSource());
    }

    void screenshots()
    {
        // Login
        verifyShown("serverField");
        verifyShown("connectButton");
        verifyShown("statusBar");
        save(QStringLiteral("login.png"));

        // Mission edit: the survey route in the document, its scan chosen.
        sortie::client::RouteDocument *doc = m_client->missions().document();
        doc->load(surveyRoute());
        doc->selectRows({2});
        QObject *mission = page("missionPage");
        QTest::keyClick(m_window, Qt::Key_2, Qt::ControlModifier);
        auto *routeLayer = mission->property("routeLayer").value<RouteLayer *>();
        QVERIFY(routeLayer);
        QTRY_VERIFY(routeLayer->width() > 600);
        routeLayer->fitToMap(60);
        auto *map = mission->property("map").value<MapView *>();
        QTest::mouseMove(m_window, map->mapToScene(QPointF(300, 300)).toPoint());
        QTRY_COMPARE(routeLayer->visibleWaypointCount(), routeLayer->count());
        QVERIFY(routeLayer->count() >= 6);
        verifyShown("routeLayer");
        verifyShown("waypointList");
        verifyShown("scaleBar");
        QTRY_VERIFY(!find<QObject>("cursorLabel")->property("text").toString().isEmpty());
        QTest::qWait(100); // let the base-map tiles land
        save(QStringLiteral("layers.png"));

        // Live telemetry
        QStandardItemModel vehicles;
        fillVehicles(vehicles);
        QObject *telemetry = page("telemetryPage");
        telemetry->setProperty("vehicleModel", QVariant::fromValue(static_cast<QObject *>(&vehicles)));
        flyVehicles(vehicles);
        QTest::keyClick(m_window, Qt::Key_3, Qt::ControlModifier);
        auto *vehicleLayer = telemetry->property("vehicleLayer").value<VehicleLayer *>();
        QCOMPARE(vehicleLayer->count(), 3);
        QVERIFY(vehicleLayer->trailPointCount(0) > 10);
        auto *telemetryMap = telemetry->property("map").value<MapView *>();
        QTRY_VERIFY(telemetryMap->width() > 600);
        telemetryMap->fitBounds(56.940, 24.080, 56.962, 24.130);
        verifyShown("vehicleLayer");
        verifyShown("vehicleList");
        QTest::qWait(100);
        save(QStringLiteral("vehicle-layer.png"));

        // Keyboard help
        QTest::keyClick(m_window, Qt::Key_F1);
        QTRY_VERIFY(m_window->property("helpOverlay").value<QObject *>()->property("opened").toBool());
        QTest::qWait(300); // the popup's fade-in
        save(QStringLiteral("shortcuts.png"));
        QTest::keyClick(m_window, Qt::Key_Escape);
        telemetry->setProperty("vehicleModel", QVariant::fromValue<QObject *>(nullptr));
    }

    // The colour scheme is a setting: the theme follows it at once, the selector shows it, and the
    // selector writes it (persisted).
    void colourSchemeFollowsTheSetting()
    {
        sortie::ui::Theme &theme = m_mainWindow->theme();
        QCOMPARE(theme.scheme(), sortie::ui::Theme::Scheme::System);
        QVERIFY(!m_window->property("dark").toBool());
        auto *box = find<QObject>("colourSchemeBox");
        QVERIFY(box);
        const QStringList codes = theme.schemeCodes();
        QCOMPARE(box->property("model").toStringList(), theme.schemeNames());
        QCOMPARE(codes.value(box->property("currentIndex").toInt()), QStringLiteral("system"));

        m_settings->setColourScheme(QStringLiteral("sunlight"));
        QCOMPARE(theme.scheme(), sortie::ui::Theme::Scheme::Sunlight);
        QTRY_VERIFY(m_window->property("dark").toBool());
        QTRY_COMPARE(codes.value(box->property("currentIndex").toInt()), QStringLiteral("sunlight"));
        QCOMPARE(m_window->property("color").value<QColor>(), QColor(Qt::black)); // the window's ground
        auto *map = page("missionPage")->property("map").value<MapView *>();
        QTRY_COMPARE(map->colours(), sortie::ui::MapPalette::sunlight());

        // The operator picks Light in the selector.
        const int light = int(codes.indexOf(QStringLiteral("light")));
        QCOMPARE(light, 1);
        box->setProperty("currentIndex", light);
        QVERIFY(QMetaObject::invokeMethod(box, "activated", Q_ARG(int, light)));
        QCOMPARE(m_settings->colourScheme(), QStringLiteral("light"));
        QCOMPARE(m_storage->value(QStringLiteral("display/colourScheme")).toString(), QStringLiteral("light"));
        QCOMPARE(theme.scheme(), sortie::ui::Theme::Scheme::Light);
        QTRY_VERIFY(!m_window->property("dark").toBool());
        QTRY_COMPARE(map->colours(), sortie::ui::MapPalette::light());
        // A choice made in the box does not unhook it from the setting.
        m_settings->setColourScheme(QStringLiteral("dark"));
        QTRY_COMPARE(codes.value(box->property("currentIndex").toInt()), QStringLiteral("dark"));
        m_settings->setColourScheme(QStringLiteral("light"));
    }

    void followsADarkPalette()
    {
        QGuiApplication::setPalette(sortie::test::darkPalette());
        QTRY_VERIFY(m_window->property("dark").toBool());
        QTest::keyClick(m_window, Qt::Key_2, Qt::ControlModifier);
        auto *map = page("missionPage")->property("map").value<MapView *>();
        QTRY_COMPARE(map->colours(), sortie::ui::MapPalette::dark());
        // The base map's tiles drawn again in the dark palette (on worker threads): the Sahara is dark land.
        const auto sahara = [map] { return map->mapToScene(map->fromCoordinate(QGeoCoordinate(23, 10))).toPoint(); };
        QTRY_COMPARE_WITH_TIMEOUT(m_window->grabWindow().pixelColor(sahara()), sortie::ui::MapPalette::dark().land, 10000);
        save(QStringLiteral("mission-dark.png"), 6);
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
