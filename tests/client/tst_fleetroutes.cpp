// FleetRoutes, every route given to a vehicle, against the simulated UgCS server over loopback: two
// emulator vehicles get routes through the open route's preparation (as the mission view does),
// the model shows both rows (planned, then uploaded, with times and colours); one flies its
// mission on auto and its row says flying, waypoint n of m, then flown; the other stays uploaded.
#include "ConnectionController.h"
#include "FleetRoutes.h"
#include "HciClient.h"
#include "MissionUploader.h"
#include "RouteDocument.h"
#include "RoutePreparation.h"
#include "RouteTiming.h"
#include "SimFixture.h"
#include "VehicleFleet.h"
#include "VehiclePalette.h"

#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace sortie;
using client::FleetRoutes;
using client::FleetRouteState;
using client::MissionUploader;

namespace {

// Three short legs east of where a vehicle stands, 12 m above the ground, 8 m/s.
mission::Route routeFrom(const QGeoCoordinate &at, const QString &name)
{
    mission::Route route;
    route.settings.name = name;
    for (double east : {12.0, 24.0, 36.0}) {
        const QGeoCoordinate p = at.atDistanceAndAzimuth(east, 90);
        mission::Waypoint w;
        w.position = {p.latitude(), p.longitude()};
        w.altitude = 25;
        w.speed = 8;
        route.segments.push_back(w);
    }
    return route;
}

QString vehicleIdOf(const vehicle::Vehicle *v)
{
    return v->protocol() + QLatin1Char(':') + v->id();
}

} // namespace

class TestFleetRoutes : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::SimFixture> m_sim;
    std::unique_ptr<hci::HciSession> m_session;
    std::unique_ptr<hci::HciClient> m_client;
    std::unique_ptr<client::ConnectionController> m_connection;
    std::unique_ptr<client::VehicleFleet> m_fleet;
    std::unique_ptr<client::RouteDocument> m_document;
    std::unique_ptr<client::RoutePreparation> m_preparation;
    std::unique_ptr<FleetRoutes> m_routes;

    vehicle::Vehicle *emu(const QString &name)
    {
        for (int row = 0; row < m_fleet->count(); ++row) {
            vehicle::Vehicle *v = m_fleet->vehicleAt(row);
            if (v->name() == name && v->isConnected() && v->position().isValid())
                return v;
        }
        return nullptr;
    }
    QVariant at(int row, FleetRoutes::Roles role) const { return m_routes->data(m_routes->index(row), role); }
    int fleetRow(const vehicle::Vehicle *v) const
    {
        for (int row = 0; row < m_fleet->count(); ++row) {
            if (m_fleet->vehicleAt(row) == v)
                return row;
        }
        return -1;
    }
    // The open route, chosen for `v` and uploaded the way the mission view's Upload does it.
    bool upload(vehicle::Vehicle *v)
    {
        MissionUploader *uploader = m_preparation->uploader();
        QSignalSpy finished(uploader, &MissionUploader::finished);
        m_preparation->setVehicleId(vehicleIdOf(v));
        m_preparation->upload();
        if (!QTest::qWaitFor([&] { return !finished.isEmpty() || uploader->isAsking(); }, 15000))
            return false;
        if (uploader->isAsking()) // warnings are asked about once
            uploader->confirm();
        if (finished.isEmpty() && !finished.wait(15000))
            return false;
        return uploader->state() == MissionUploader::State::Done;
    }

private slots:
    void init()
    {
        m_sim = std::make_unique<test::SimFixture>();
        m_session = std::make_unique<hci::HciSession>();
        m_client = std::make_unique<hci::HciClient>(m_session.get());
        m_connection = std::make_unique<client::ConnectionController>(m_session.get());
        m_fleet = std::make_unique<client::VehicleFleet>(m_client.get());
        m_document = std::make_unique<client::RouteDocument>();
        m_preparation = std::make_unique<client::RoutePreparation>(m_document.get());
        m_preparation->setFleet(m_fleet.get());
        m_routes = std::make_unique<FleetRoutes>(m_fleet.get(), m_document.get(), m_preparation.get());
        QSignalSpy ready(m_connection.get(), &client::ConnectionController::ready);
        m_connection->connectToServer(m_sim->address(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(ready.wait(10000));
        QTRY_VERIFY_WITH_TIMEOUT(emu(QStringLiteral("EMU-101")) && emu(QStringLiteral("EMU-102")), 10000);
    }

    void cleanup()
    {
        m_routes.reset();
        m_preparation.reset();
        m_document.reset();
        m_fleet.reset();
        m_connection.reset();
        m_client.reset();
        m_session.reset();
        m_sim.reset();
    }

    void everyRouteOfTheFleetWithItsStateThenOneFlies()
    {
        vehicle::Vehicle *first = emu(QStringLiteral("EMU-101"));
        vehicle::Vehicle *second = emu(QStringLiteral("EMU-102"));
        QCOMPARE(m_routes->count(), 0);

        // The open route chosen for a vehicle is planned: its row is there before anything is sent.
        m_document->load(routeFrom(first->position(), QStringLiteral("North field")));
        m_preparation->setVehicleId(vehicleIdOf(first));
        QCOMPARE(m_routes->count(), 1);
        QCOMPARE(at(0, FleetRoutes::StateRole).toString(), QStringLiteral("planned"));
        QCOMPARE(at(0, FleetRoutes::StateTextRole).toString(), QStringLiteral("planned"));
        QCOMPARE(at(0, FleetRoutes::RouteNameRole).toString(), QStringLiteral("North field"));
        QCOMPARE(at(0, FleetRoutes::VehicleNameRole).toString(), QStringLiteral("EMU-101"));
        QCOMPARE(at(0, FleetRoutes::OpenRole).toBool(), true);
        QCOMPARE(at(0, FleetRoutes::ColorRole).value<QColor>(), client::vehicleColor(fleetRow(first)));
        QCOMPARE(at(0, FleetRoutes::PathRole).value<QPolygonF>().size(), 3);
        // The time model's figure: 24 m between the first and the last waypoint at 8 m/s.
        const double plannedSeconds = at(0, FleetRoutes::FlightSecondsRole).toDouble();
        const auto timeline = mission::timeRoute(m_document->route(), mission::timingOf(m_document->route().settings));
        QVERIFY(timeline);
        QCOMPARE(plannedSeconds, timeline->totalSeconds());
        QVERIFY2(std::abs(plannedSeconds - 24.0 / 8) < 0.1, qPrintable(QString::number(plannedSeconds)));
        QVERIFY(std::isnan(at(0, FleetRoutes::ElapsedSecondsRole).toDouble())); // not flying: missing, not 0

        // Uploaded: the same row, now the vehicle's (the open route equals what it holds).
        QVERIFY(upload(first));
        QCOMPARE(m_routes->count(), 1);
        QCOMPARE(at(0, FleetRoutes::StateRole).toString(), QStringLiteral("uploaded"));
        QVERIFY(at(0, FleetRoutes::StateTextRole).toString().startsWith(QStringLiteral("uploaded ")));
        QVERIFY(at(0, FleetRoutes::UploadedAtRole).toDateTime().isValid());

        // A second route for the second vehicle: both rows, each in its vehicle's colour.
        m_document->load(routeFrom(second->position(), QStringLiteral("South field")));
        QCOMPARE(m_routes->count(), 2); // still chosen for the first vehicle, and not what it holds: planned for it
        QCOMPARE(at(1, FleetRoutes::VehicleNameRole).toString(), QStringLiteral("EMU-101"));
        m_preparation->setVehicleId(vehicleIdOf(second));
        QCOMPARE(m_routes->count(), 2);
        QCOMPARE(at(1, FleetRoutes::VehicleNameRole).toString(), QStringLiteral("EMU-102"));
        QCOMPARE(at(1, FleetRoutes::StateRole).toString(), QStringLiteral("planned"));
        QCOMPARE(at(0, FleetRoutes::OpenRole).toBool(), false);
        QVERIFY(upload(second));
        QCOMPARE(m_routes->count(), 2);
        QCOMPARE(at(0, FleetRoutes::StateRole).toString(), QStringLiteral("uploaded"));
        QCOMPARE(at(1, FleetRoutes::StateRole).toString(), QStringLiteral("uploaded"));
        QCOMPARE(at(1, FleetRoutes::RouteNameRole).toString(), QStringLiteral("South field"));
        QCOMPARE(at(1, FleetRoutes::ColorRole).value<QColor>(), client::vehicleColor(fleetRow(second)));
        QVERIFY(at(0, FleetRoutes::ColorRole).value<QColor>() != at(1, FleetRoutes::ColorRole).value<QColor>());

        // What deconfliction reads: each route as uploaded, its vehicle, its state; no start before it flies.
        std::vector<client::FleetRoute> routes = m_routes->routes();
        QCOMPARE(routes.size(), size_t(2));
        QCOMPARE(routes[0].vehicleId, vehicleIdOf(first));
        QCOMPARE(routes[0].route.settings.name, QStringLiteral("North field"));
        QCOMPARE(routes[1].vehicleId, vehicleIdOf(second));
        QVERIFY(routes[1].route == m_document->route());
        QCOMPARE(routes[1].state, FleetRouteState::Uploaded);
        QVERIFY(!routes[1].startedAt.isValid());
        QVERIFY(!routes[1].progress);

        // The second vehicle flies its mission: its row says so, waypoint by waypoint; the first stays uploaded.
        const int count = int(second->mission().size());
        QVERIFY(count >= 3);
        QSignalSpy commands(second, &vehicle::Vehicle::commandFinished);
        second->arm();
        QTRY_COMPARE(commands.count(), 1);
        QVERIFY2(commands.last().at(1).toBool(), qPrintable(commands.last().at(2).toString()));
        second->setMode(QStringLiteral("auto"));
        QTRY_COMPARE(commands.count(), 2);
        QVERIFY2(commands.last().at(1).toBool(), qPrintable(commands.last().at(2).toString()));
        QTRY_COMPARE_WITH_TIMEOUT(at(1, FleetRoutes::StateRole).toString(), QStringLiteral("flying"), 15000);
        const QRegularExpression flying(QStringLiteral("^flying: waypoint (\\d+) of %1$").arg(count));
        const auto match = flying.match(at(1, FleetRoutes::StateTextRole).toString());
        QVERIFY2(match.hasMatch(), qPrintable(at(1, FleetRoutes::StateTextRole).toString()));
        QVERIFY(match.captured(1).toInt() >= 1 && match.captured(1).toInt() <= count);
        QVERIFY(at(1, FleetRoutes::ElapsedSecondsRole).toDouble() >= 0);
        routes = m_routes->routes();
        QCOMPARE(routes[1].state, FleetRouteState::Flying);
        QVERIFY(routes[1].startedAt.isValid());
        QVERIFY(routes[1].progress);
        QCOMPARE(routes[1].progress->count, count);
        QCOMPARE(routes[0].state, FleetRouteState::Uploaded);
        // It reaches a later waypoint, then completes the route.
        QTRY_VERIFY_WITH_TIMEOUT(m_routes->routes()[1].progress && m_routes->routes()[1].progress->waypoint >= 2, 30000);
        QTRY_COMPARE_WITH_TIMEOUT(at(1, FleetRoutes::StateRole).toString(), QStringLiteral("flown"), 60000);
        QCOMPARE(at(0, FleetRoutes::StateRole).toString(), QStringLiteral("uploaded"));
    }

    // An edit after the upload makes the open route planned again beside what the vehicle holds.
    void anEditAfterTheUploadIsPlannedBesideTheUploadedRoute()
    {
        vehicle::Vehicle *first = emu(QStringLiteral("EMU-101"));
        m_document->load(routeFrom(first->position(), QStringLiteral("North field")));
        QVERIFY(upload(first));
        QCOMPARE(m_routes->count(), 1);
        QVERIFY(m_document->editor()->setAltitude({1}, 40));
        QTRY_COMPARE(m_routes->count(), 2);
        QCOMPARE(at(0, FleetRoutes::StateRole).toString(), QStringLiteral("uploaded"));
        QCOMPARE(at(0, FleetRoutes::OpenRole).toBool(), false);
        QCOMPARE(at(1, FleetRoutes::StateRole).toString(), QStringLiteral("planned"));
        QCOMPARE(at(1, FleetRoutes::OpenRole).toBool(), true);
        // Undone: the open route is what the vehicle holds again; one row.
        m_document->undo();
        QTRY_COMPARE(m_routes->count(), 1);
        QCOMPARE(at(0, FleetRoutes::OpenRole).toBool(), true);
    }
};

QTEST_GUILESS_MAIN(TestFleetRoutes)
#include "tst_fleetroutes.moc"
