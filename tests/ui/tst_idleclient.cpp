// The whole client idling against the embedded simulator's three parked vehicles (what
// scripts/bench-idle.sh measures as CPU): their telemetry keeps arriving at 10 Hz with the same
// values, and not one map layer on either page asks for a picture (MapLayer's test hook). The
// waits count telemetry samples, not time.
#include "ClientWindow.h"
#include "QuickScene.h"
#include "MapLayer.h"
#include "Vehicle.h"
#include "VehicleFleet.h"
#include "VehicleLayer.h"

#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <map>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;
using sortie::test::ClientWindow;
using sortie::vehicle::TelemetryField;

namespace {

// Every map layer of the window: its class, objectName and place among them.
std::map<QString, int> repaintRequests(QQuickWindow *window)
{
    std::map<QString, int> requests;
    const auto layers = window->findChildren<ui::MapLayer *>();
    for (int i = 0; i < layers.size(); ++i) {
        const QString name = QStringLiteral("%1 %2 #%3")
                                 .arg(QString::fromLatin1(layers[i]->metaObject()->className()), layers[i]->objectName())
                                 .arg(i);
        requests[name] = layers[i]->repaintRequests();
    }
    return requests;
}

// Waits until every vehicle of the fleet has `more` telemetry samples of its position beyond now.
bool waitForSamples(client::VehicleFleet &fleet, size_t more)
{
    std::vector<size_t> target;
    for (int row = 0; row < fleet.rowCount(); ++row)
        target.push_back(fleet.vehicleAt(row)->history().series(TelemetryField::Latitude).size() + more);
    return QTest::qWaitFor([&] {
        for (int row = 0; row < fleet.rowCount(); ++row)
            if (fleet.vehicleAt(row)->history().series(TelemetryField::Latitude).size() < target[size_t(row)])
                return false;
        return true;
    }, 30000);
}

} // namespace

class TestIdleClient : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { sortie::test::useSoftwareRendering(); }

    void parkedVehiclesRepaintNoLayer()
    {
        ClientWindow::Options options;
        options.vciVehicles = 0; // the server's three vehicles, on the ground
        options.mannedTraffic = false; // nothing else moves
        ClientWindow client(options);
        QVERIFY2(client.isReady(), qPrintable(client.error()));
        QVERIFY(client.logIn());
        client.showPage(1);
        auto *vehicles = client.find<ui::VehicleLayer>(QStringLiteral("missionVehicleLayer"));
        QVERIFY(vehicles);
        QTRY_COMPARE_WITH_TIMEOUT(vehicles->positionedCount(), 3, 20000);
        QCOMPARE(client.fleet().rowCount(), 3);
        // Settled: homes, names and the first frames in.
        QVERIFY(waitForSamples(client.fleet(), 10));
        QVERIFY(sortie::test::waitForFrame(client.window()));
        const auto before = repaintRequests(client.window());
        QVERIFY2(before.size() >= 15, qPrintable(QString::number(before.size()))); // both pages' layers
        const quint64 notified = client.fleet().vehicleAt(0)->telemetryNotifications();
        QVERIFY(waitForSamples(client.fleet(), 30)); // three seconds of telemetry from each vehicle
        QCOMPARE(client.fleet().vehicleAt(0)->telemetryNotifications(), notified); // nothing new in it
        const auto after = repaintRequests(client.window());
        for (const auto &[name, count] : before)
            QVERIFY2(after.at(name) == count, qPrintable(QStringLiteral("%1 asked for %2 pictures").arg(name).arg(after.at(name) - count)));
    }
};

QTEST_MAIN(TestIdleClient)
#include "tst_idleclient.moc"
