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

// The vehicle's last value of every field ("-" for none yet), to name what changed.
std::map<std::string, QString> lastValues(const vehicle::Vehicle &vehicle)
{
    std::map<std::string, QString> values;
    for (size_t i = 0; i < vehicle::kTelemetryFieldCount; ++i) {
        const auto field = TelemetryField(i);
        const auto last = vehicle.last(field);
        values[std::string(vehicle::fieldName(field))] = last ? QString::number(last->value, 'g', 17) : QStringLiteral("-");
    }
    return values;
}

QString changedFields(const std::map<std::string, QString> &before, const std::map<std::string, QString> &after)
{
    QStringList changed;
    for (const auto &[name, value] : before)
        if (after.at(name) != value)
            changed << QStringLiteral("%1 %2 -> %3").arg(QString::fromStdString(name), value, after.at(name));
    return changed.join(QStringLiteral(", "));
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
        // Settled: homes, names, modes and the first frames in. On a loaded machine some of them
        // (a home, a mission state) come after the first samples: settled is two seconds of samples
        // from every vehicle in which the first vehicle's values did not change.
        const vehicle::Vehicle &first = *client.fleet().vehicleAt(0);
        bool settled = false;
        for (int round = 0; round < 10 && !settled; ++round) {
            const quint64 count = first.telemetryNotifications();
            const auto values = lastValues(first);
            QVERIFY(waitForSamples(client.fleet(), 20));
            settled = first.telemetryNotifications() == count;
            if (!settled)
                qInfo().noquote() << "not settled yet:" << changedFields(values, lastValues(first));
        }
        QVERIFY2(settled, "the parked vehicle's telemetry kept changing");
        QVERIFY(sortie::test::waitForFrame(client.window()));
        const auto before = repaintRequests(client.window());
        QVERIFY2(before.size() >= 15, qPrintable(QString::number(before.size()))); // both pages' layers
        const quint64 notified = first.telemetryNotifications();
        const auto values = lastValues(first);
        QVERIFY(waitForSamples(client.fleet(), 30)); // three seconds of telemetry from each vehicle
        // Nothing new in it.
        QVERIFY2(first.telemetryNotifications() == notified, qPrintable(changedFields(values, lastValues(first))));
        const auto after = repaintRequests(client.window());
        for (const auto &[name, count] : before)
            QVERIFY2(after.at(name) == count, qPrintable(QStringLiteral("%1 asked for %2 pictures").arg(name).arg(after.at(name) - count)));
    }
};

QTEST_MAIN(TestIdleClient)
#include "tst_idleclient.moc"
