// The fly view's zone alert, offscreen in the real window against a simulated VCI vehicle over a
// real socket: the client graph's ZoneAlertMonitor is given a keep-out zone ahead of the vehicle
// (as the zone store will give it); flown towards it, the proximity banner shows "Airspace: ...
// enters 'tower' in N s", and the command log has that line once.
#include "ClientWindow.h"
#include "QuickScene.h"
#include "VehicleLayer.h"
#include "ZoneAlertMonitor.h"

#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

class TestZoneAlertBanner : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_client;

private slots:
    void initTestCase() { test::useSoftwareRendering(); }
    void cleanupTestCase() { m_client.reset(); }

    void alertInTheFlyViewBanner()
    {
        test::ClientWindow::Options options;
        options.vciTimeScale = 4;
        m_client = std::make_unique<test::ClientWindow>(options);
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
        airspace::ZoneAlertMonitor *monitor = m_client->graph().zoneAlerts();
        QVERIFY(monitor);
        QVERIFY(m_client->addVciVehicles());
        QTest::keyClick(m_client->window(), Qt::Key_3, Qt::ControlModifier);
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        QTRY_COMPARE(layer->positionedCount(), 1);
        vehicle::Vehicle *v = m_client->fleet().vehicleAt(0);
        v->arm();
        QTRY_VERIFY_WITH_TIMEOUT(v->armed(), 10000);
        v->takeoff(30);
        QTRY_VERIFY_WITH_TIMEOUT(v->altitudeAgl() > 29 && v->mode() == QLatin1String("hold"), 30000);
        auto *banner = m_client->find(QStringLiteral("alertBanner"));
        QVERIFY(banner && !banner->isVisible());

        const QGeoCoordinate here = v->position();
        airspace::Zone tower;
        tower.name = QStringLiteral("tower");
        const QGeoCoordinate centre = here.atDistanceAndAzimuth(400, 90);
        tower.shape = airspace::ZoneCircle{{centre.latitude(), centre.longitude()}, 60};
        monitor->setZones(std::make_shared<const airspace::ZoneSet>(std::vector<airspace::Zone>{tower}));
        const QGeoCoordinate beyond = here.atDistanceAndAzimuth(1000, 90);
        m_client->fleet().goTo(0, beyond.latitude(), beyond.longitude());

        QTRY_VERIFY_WITH_TIMEOUT(banner->isVisible(), 30000);
        QQuickItem *row = test::findItem(banner, QStringLiteral("zoneAlert"));
        QVERIFY(row);
        const QString shown = row->property("text").toString();
        QVERIFY2(shown.startsWith(QStringLiteral("Airspace: %1 enters 'tower' in ").arg(v->name())), qPrintable(shown));
        QVERIFY(test::waitForFrame(m_client->window()));
        const vehicle::CommandLog &log = *m_client->fleet().commandLog();
        int lines = 0;
        for (int i = 0; i < log.count(); ++i)
            lines += log.at(i).status == vehicle::CommandLog::Status::Alert && log.at(i).command.contains(QStringLiteral("'tower'"));
        QCOMPARE(lines, 1);
    }
};

QTEST_MAIN(TestZoneAlertBanner)
#include "tst_zonealertbanner.moc"
