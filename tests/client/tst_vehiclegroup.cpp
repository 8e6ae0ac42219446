// VehicleGroup against the simulated UgCS server's three vehicles: the one question names every
// ticked vehicle; the command goes to each, and a vehicle that refuses (take-off while disarmed)
// does not stop the others; each answer is in the command log and in the group's result; a vehicle
// that leaves the fleet leaves the group.
#include "CommandLog.h"
#include "ConnectionController.h"
#include "HciClient.h"
#include "SimFixture.h"
#include "VehicleFleet.h"
#include "VehicleGroup.h"

#include <QSignalSpy>
#include <QTest>

using namespace sortie;
using client::CommandPolicy;
using client::VehicleFleet;

class TestVehicleGroup : public QObject
{
    Q_OBJECT

    static QString idOf(const VehicleFleet &fleet, int row) { return fleet.index(row).data(VehicleFleet::VehicleIdRole).toString(); }

    static int logged(const vehicle::CommandLog &log, const QString &vehicle, const QString &command, vehicle::CommandLog::Status status)
    {
        int n = 0;
        for (int row = 0; row < log.count(); ++row) {
            const auto &e = log.at(row);
            n += e.vehicle == vehicle && e.command.startsWith(command) && e.status == status ? 1 : 0;
        }
        return n;
    }

private slots:
    void commandsGoToEveryTickedVehicle()
    {
        test::SimFixture sim;
        hci::HciSession session;
        hci::HciClient client(&session);
        client::ConnectionController connection(&session);
        VehicleFleet fleet(&client);
        QVERIFY(connection.connectToServer(sim.address(), QStringLiteral("admin"), QStringLiteral("admin")));
        QTRY_COMPARE_WITH_TIMEOUT(fleet.count(), 3, 10000);
        for (int row = 0; row < 3; ++row)
            QTRY_COMPARE_WITH_TIMEOUT(fleet.vehicleAt(row)->linkState(), vehicle::VehicleLink::State::Connected, 10000);
        client::VehicleGroup &group = *fleet.group();
        const QStringList names{fleet.vehicleAt(0)->name(), fleet.vehicleAt(1)->name(), fleet.vehicleAt(2)->name()};

        // Ticking shows in the fleet's rows; the group lists them in the fleet's order.
        QSignalSpy rows(&fleet, &QAbstractItemModel::dataChanged);
        group.setChosen(idOf(fleet, 1), true);
        group.setChosen(idOf(fleet, 0), true);
        group.setChosen(QStringLiteral("HCI:no-such-vehicle"), true);  // not in the fleet: not chosen
        QCOMPARE(group.count(), 2);
        QCOMPARE(group.names(), (QStringList{names[0], names[1]}));
        QVERIFY(fleet.index(0).data(VehicleFleet::ChosenRole).toBool());
        QVERIFY(!fleet.index(2).data(VehicleFleet::ChosenRole).toBool());
        QVERIFY(!rows.isEmpty());

        // One question naming both; then both arm.
        const QString armQuestion = group.confirmation(CommandPolicy::Command::Arm);
        QVERIFY2(armQuestion.contains(names[0]) && armQuestion.contains(names[1]) && !armQuestion.contains(names[2]), qPrintable(armQuestion));
        QCOMPARE(group.send(CommandPolicy::Command::Arm), 2);
        QTRY_VERIFY_WITH_TIMEOUT(fleet.vehicleAt(0)->armed() && fleet.vehicleAt(1)->armed(), 10000);
        QTRY_VERIFY2(group.result().contains(QStringLiteral("2 of 2")), qPrintable(group.result()));
        QVERIFY(!fleet.vehicleAt(2)->armed());

        // Take-off to all three: the disarmed one refuses, the other two climb anyway.
        group.setChosen(idOf(fleet, 2), true);
        const QString takeoffQuestion = group.confirmation(CommandPolicy::Command::TakeOff);
        for (const QString &name : names)
            QVERIFY2(takeoffQuestion.contains(name + QStringLiteral(" (20 m)")), qPrintable(takeoffQuestion));
        QCOMPARE(group.send(CommandPolicy::Command::TakeOff), 3);
        QTRY_VERIFY2_WITH_TIMEOUT(group.result().contains(QStringLiteral("3 of 3")), qPrintable(group.result()), 10000);
        QVERIFY2(group.result().contains(names[2] + QStringLiteral(" failed: ")) && group.result().contains(QStringLiteral("arm before take-off")),
                 qPrintable(group.result()));
        QVERIFY2(group.result().contains(names[0] + QStringLiteral(" done")), qPrintable(group.result()));
        QTRY_VERIFY_WITH_TIMEOUT(fleet.vehicleAt(0)->altitudeAgl() > 3 && fleet.vehicleAt(1)->altitudeAgl() > 3, 30000);
        QVERIFY(!(fleet.vehicleAt(2)->altitudeAgl() > 0.5));

        // Each vehicle's command and answer is in the command log, as a single command's would be.
        const vehicle::CommandLog &log = *fleet.commandLog();
        QCOMPARE(logged(log, names[0], QStringLiteral("arm"), vehicle::CommandLog::Status::Done), 1);
        QCOMPARE(logged(log, names[1], QStringLiteral("arm"), vehicle::CommandLog::Status::Done), 1);
        QCOMPARE(logged(log, names[0], QStringLiteral("takeoff"), vehicle::CommandLog::Status::Done), 1);
        QCOMPARE(logged(log, names[2], QStringLiteral("takeoff"), vehicle::CommandLog::Status::Failed), 1);

        // The vehicles leave with the session, and the group with them.
        connection.disconnectFromServer();
        QTRY_COMPARE(fleet.count(), 0);
        QCOMPARE(group.count(), 0);
        QVERIFY(group.confirmation(CommandPolicy::Command::Land).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestVehicleGroup)
#include "tst_vehiclegroup.moc"
