// VehicleFleet against the simulators: the server's vehicles over HCI and a VCI vehicle side by
// side, telemetry moving them, a command changing a vehicle's state, click-and-go.
#include "ConnectionController.h"
#include "HciClient.h"
#include "SimFixture.h"
#include "SimVciFleet.h"
#include "SimVciListener.h"
#include "VehicleFleet.h"

#include <QSignalSpy>
#include <QTest>

using namespace sortie;
using client::VehicleFleet;

class TestVehicleFleet : public QObject
{
    Q_OBJECT

private slots:
    void hciAndVciSideBySide()
    {
        test::SimFixture sim;
        sim::SimVciFleetOptions options;
        options.count = 1;
        options.firstPort = 0;
        sim::SimVciFleet vci(options);
        QString error;
        QVERIFY2(vci.start(&error), qPrintable(error));

        hci::HciSession session;
        hci::HciClient client(&session);
        client::ConnectionController connection(&session);
        VehicleFleet fleet(&client);
        QVERIFY(connection.connectToServer(sim.address(), QStringLiteral("admin"), QStringLiteral("admin")));
        QTRY_COMPARE_WITH_TIMEOUT(fleet.count(), 3, 10000);
        QVERIFY(!fleet.addVciVehicle(QStringLiteral("udp://nowhere")));
        QVERIFY(!fleet.message().isEmpty());
        QVERIFY(fleet.addVciVehicle(QStringLiteral("tcp://127.0.0.1:%1").arg(vci.listeners().front()->port())));
        QCOMPARE(fleet.count(), 4);

        QStringList protocols;
        for (int row = 0; row < fleet.count(); ++row)
            protocols.append(fleet.index(row).data(VehicleFleet::ProtocolRole).toString());
        QCOMPARE(protocols, (QStringList{"HCI", "HCI", "HCI", "VCI"}));

        // Every vehicle connects and reports a position; HCI and VCI alike.
        for (int row = 0; row < fleet.count(); ++row) {
            QTRY_VERIFY_WITH_TIMEOUT(fleet.index(row).data(VehicleFleet::LatitudeRole).isValid(), 10000);
            QTRY_COMPARE_WITH_TIMEOUT(fleet.index(row).data(VehicleFleet::LinkStateRole).toString(), QStringLiteral("Connected"), 10000);
            QVERIFY(!fleet.index(row).data(VehicleFleet::StaleRole).toBool());
            const double lat = fleet.index(row).data(VehicleFleet::LatitudeRole).toDouble();
            QVERIFY2(lat > 56.8 && lat < 57.1, qPrintable(QString::number(lat))); // around Riga, in degrees
        }
        QVERIFY(fleet.vehicleAt(3)->history().series(vehicle::TelemetryField::Latitude).size() > 0);

        // Arming a VCI vehicle and an HCI vehicle changes what they report.
        for (int row : {0, 3}) {
            QSignalSpy result(&fleet, &VehicleFleet::commandResultChanged);
            fleet.vehicleAt(row)->arm();
            QVERIFY(result.wait(10000));
            QVERIFY2(fleet.commandResult().contains(QStringLiteral("done")), qPrintable(fleet.commandResult()));
            QTRY_VERIFY_WITH_TIMEOUT(fleet.index(row).data(VehicleFleet::ArmedRole).toBool(), 10000);
        }
    }

    void vehiclesGoWhenTheSessionCloses()
    {
        test::SimFixture sim;
        hci::HciSession session;
        hci::HciClient client(&session);
        client::ConnectionController connection(&session);
        VehicleFleet fleet(&client);
        QVERIFY(connection.connectToServer(sim.address(), QStringLiteral("admin"), QStringLiteral("admin")));
        QTRY_COMPARE_WITH_TIMEOUT(fleet.count(), 3, 10000);
        connection.disconnectFromServer();
        QTRY_COMPARE(fleet.count(), 0);
    }
};

QTEST_GUILESS_MAIN(TestVehicleFleet)
#include "tst_vehiclefleet.moc"
