// Deconfliction before upload, against the simulated UgCS server: EMU-101 holds a route east along
// a line; the open route, chosen for EMU-102, flies the same line west at the same height and
// speed, so if both start now they meet head-on in the middle. While EMU-101 only holds its route,
// the open route gets a warning naming it; once EMU-101 flies it, an error, and the upload to
// EMU-102 is refused with the reason. The conflict's positions and time are what the views get.
#include "ConnectionController.h"
#include "FleetConflictRule.h"
#include "FleetRoutes.h"
#include "HciClient.h"
#include "MissionUploader.h"
#include "RouteAnalyzer.h"
#include "RouteDeconfliction.h"
#include "RouteDocument.h"
#include "RoutePreparation.h"
#include "SimFixture.h"
#include "VehicleFleet.h"

#include <QSignalSpy>
#include <QTest>

using namespace sortie;
using client::MissionUploader;

namespace {

// Along the line east of `origin`, from `fromEast` to `toEast` metres, 25 m above the ground, 6 m/s.
mission::Route lineRoute(const QGeoCoordinate &origin, double fromEast, double toEast, const QString &name)
{
    mission::Route route;
    route.settings.name = name;
    const int steps = 4;
    for (int i = 0; i <= steps; ++i) {
        const double east = fromEast + (toEast - fromEast) * i / steps;
        const QGeoCoordinate p = east >= 0 ? origin.atDistanceAndAzimuth(east, 90) : origin.atDistanceAndAzimuth(-east, 270);
        mission::Waypoint w;
        w.position = {p.latitude(), p.longitude()};
        w.altitude = 25;
        w.speed = 6;
        route.segments.push_back(w);
    }
    return route;
}

QString vehicleIdOf(const vehicle::Vehicle *v) { return v->protocol() + QLatin1Char(':') + v->id(); }

} // namespace

class TestRouteDeconfliction : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::SimFixture> m_sim;
    std::unique_ptr<hci::HciSession> m_session;
    std::unique_ptr<hci::HciClient> m_client;
    std::unique_ptr<client::ConnectionController> m_connection;
    std::unique_ptr<client::VehicleFleet> m_fleet;
    std::unique_ptr<client::RouteDocument> m_document;
    std::unique_ptr<client::RoutePreparation> m_preparation;
    std::unique_ptr<client::FleetRoutes> m_routes;
    std::unique_ptr<deconfliction::RouteDeconfliction> m_deconfliction;

    vehicle::Vehicle *emu(const QString &name)
    {
        for (int row = 0; row < m_fleet->count(); ++row) {
            vehicle::Vehicle *v = m_fleet->vehicleAt(row);
            if (v->name() == name && v->isConnected() && v->position().isValid())
                return v;
        }
        return nullptr;
    }
    std::vector<mission::ValidationIssue> issues(const QString &rule)
    {
        m_document->analyzer()->recomputeNow();
        std::vector<mission::ValidationIssue> found;
        for (const auto &i : m_document->analyzer()->validation().issues)
            if (i.rule == rule)
                found.push_back(i);
        return found;
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
        m_routes = std::make_unique<client::FleetRoutes>(m_fleet.get(), m_document.get(), m_preparation.get());
        m_deconfliction = std::make_unique<deconfliction::RouteDeconfliction>(m_routes.get(), m_preparation.get(), m_document->analyzer());
        QSignalSpy ready(m_connection.get(), &client::ConnectionController::ready);
        m_connection->connectToServer(m_sim->address(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(ready.wait(10000));
        QTRY_VERIFY_WITH_TIMEOUT(emu(QStringLiteral("EMU-101")) && emu(QStringLiteral("EMU-102")), 10000);
    }

    void cleanup()
    {
        m_deconfliction.reset();
        m_routes.reset();
        m_preparation.reset();
        m_document.reset();
        m_fleet.reset();
        m_connection.reset();
        m_client.reset();
        m_session.reset();
        m_sim.reset();
    }

    void headOnWithAHeldThenAFlyingRoute()
    {
        vehicle::Vehicle *first = emu(QStringLiteral("EMU-101"));
        vehicle::Vehicle *second = emu(QStringLiteral("EMU-102"));
        const QGeoCoordinate origin = first->position();

        // EMU-101 gets the eastbound route: uploaded, no conflict with anything.
        m_document->load(lineRoute(origin, 10, 250, QStringLiteral("Eastbound")));
        m_preparation->setVehicleId(vehicleIdOf(first));
        QVERIFY(issues(QStringLiteral("deconfliction-uploaded")).empty());
        MissionUploader *uploader = m_preparation->uploader();
        QSignalSpy finished(uploader, &MissionUploader::finished);
        m_preparation->upload();
        QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty() || uploader->isAsking(); }, 15000));
        if (uploader->isAsking())
            uploader->confirm();
        QTRY_COMPARE_WITH_TIMEOUT(uploader->state(), MissionUploader::State::Done, 15000);

        // The open route, westbound on the same line, for EMU-102: head-on if both start now.
        m_document->load(lineRoute(origin, 250, 10, QStringLiteral("Westbound")));
        m_preparation->setVehicleId(vehicleIdOf(second));
        auto warnings = issues(QStringLiteral("deconfliction-uploaded"));
        QCOMPARE(warnings.size(), size_t(1));
        QCOMPARE(warnings.front().severity, mission::Severity::Warning);
        QVERIFY2(warnings.front().message.contains(QStringLiteral("EMU-101's uploaded \"Eastbound\"")), qPrintable(warnings.front().message));
        QVERIFY(warnings.front().segment >= 0);
        QCOMPARE(m_deconfliction->count(), 1);
        const deconfliction::Conflict &conflict = m_deconfliction->conflicts().front().conflict;
        // 240 m apart closing at 12 m/s: they meet about 20 s after the start, in the middle.
        QVERIFY2(conflict.time > 5 && conflict.time < 40, qPrintable(QString::number(conflict.time)));
        QVERIFY(conflict.horizontal < 20);
        QVERIFY(conflict.vertical < 15);
        // The row the route panel shows says the same, by role.
        QCOMPARE(m_deconfliction->rowCount(), 1);
        const QModelIndex row = m_deconfliction->index(0);
        QCOMPARE(row.data(m_deconfliction->roleNames().key("time")).toDouble(), conflict.time);
        QCOMPARE(row.data(m_deconfliction->roleNames().key("otherVehicle")).toString(), QStringLiteral("EMU-101"));
        QCOMPARE(row.data(m_deconfliction->roleNames().key("flying")).toBool(), false);
        const QGeoCoordinate own(conflict.firstAt.position.latitude, conflict.firstAt.position.longitude);
        const QGeoCoordinate middle = origin.atDistanceAndAzimuth(130, 90);
        QVERIFY2(own.distanceTo(middle) < 60, qPrintable(QString::number(own.distanceTo(middle))));

        // The route EMU-102 would fly is not another's: chosen for EMU-101 itself, nothing to say.
        m_preparation->setVehicleId(vehicleIdOf(first));
        QVERIFY(issues(QStringLiteral("deconfliction-uploaded")).empty());
        m_preparation->setVehicleId(vehicleIdOf(second));

        // EMU-101 takes off on its mission: now an error, and the upload to EMU-102 is refused.
        QSignalSpy commands(first, &vehicle::Vehicle::commandFinished);
        first->arm();
        QTRY_COMPARE(commands.count(), 1);
        QVERIFY(commands.last().at(1).toBool());
        first->setMode(QStringLiteral("auto"));
        QTRY_COMPARE(commands.count(), 2);
        QTRY_VERIFY_WITH_TIMEOUT(!issues(QStringLiteral("deconfliction-flying")).empty(), 20000);
        const auto errors = issues(QStringLiteral("deconfliction-flying"));
        QCOMPARE(errors.front().severity, mission::Severity::Error);
        QVERIFY2(errors.front().message.contains(QStringLiteral("EMU-101, flying \"Eastbound\"")), qPrintable(errors.front().message));

        finished.clear();
        m_preparation->upload();
        QTRY_VERIFY_WITH_TIMEOUT(!finished.isEmpty(), 15000);
        QCOMPARE(uploader->state(), MissionUploader::State::Failed);
        QVERIFY2(m_preparation->message().contains(QStringLiteral("EMU-101")), qPrintable(m_preparation->message()));
        QVERIFY(second->mission().empty()); // nothing reached it
    }
};

QTEST_GUILESS_MAIN(TestRouteDeconfliction)
#include "tst_routedeconfliction.moc"
