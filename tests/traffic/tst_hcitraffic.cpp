// The server's ADS-B list: HciTrafficSource asks the simulated UgCS server (sortie-sim's HCI
// server, in-process) about the area the map shows and puts the answer into the picture.
#include "HciClient.h"
#include "HciServer.h"
#include "HciSession.h"
#include "HciTrafficSource.h"
#include "SimTraffic.h"
#include "SimWorld.h"
#include "TrafficPicture.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace sortie;
using namespace sortie::traffic;

class TestHciTraffic : public QObject
{
    Q_OBJECT

    std::unique_ptr<sim::SimWorld> m_world;
    std::unique_ptr<sim::HciServer> m_server;

private slots:
    void init()
    {
        m_world = std::make_unique<sim::SimWorld>();
        m_server = std::make_unique<sim::HciServer>(*m_world);
        QVERIFY(m_server->listen(QHostAddress::LocalHost, 0));
    }
    void cleanup()
    {
        m_server.reset();
        m_world.reset();
    }

    void theServersAircraftAroundTheView()
    {
        hci::HciSession session;
        hci::HciClient client(&session);
        TrafficPicture picture;
        HciTrafficSource source(&client, &picture);
        source.setArea(sim::SimTraffic::kCentreLatitude, sim::SimTraffic::kCentreLongitude, 10000);
        QCOMPARE(source.state(), HciTrafficSource::State::Idle); // not signed in: nothing asked
        session.open(QStringLiteral("127.0.0.1"), m_server->port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), HciTrafficSource::State::Answered, 15000);
        QCOMPARE(source.lastCount(), 3);
        QCOMPARE(picture.count(), 3);
        const auto expected = m_world->traffic().aircraftNow();
        for (const sim::SimAircraft &e : expected) {
            const TrafficAircraft *a = picture.find(e.address);
            QVERIFY(a);
            QCOMPARE(a->state.callsign.value(), e.callsign);
            QCOMPARE(a->state.source, TrafficSource::Server);
            QCOMPARE(a->state.altitudeReference, AltitudeReference::MeanSeaLevel);
            // Within the ground it covers in the few seconds between the answer and now.
            const double north = (*a->state.latitude - e.latitude) * 111195.0;
            const double east = (*a->state.longitude - e.longitude) * 111195.0 * std::cos(e.latitude * M_PI / 180);
            QVERIFY2(std::hypot(north, east) < e.groundSpeedMps * 5, qPrintable(e.callsign));
            QVERIFY(qAbs(*a->state.groundSpeedMps - e.groundSpeedMps) < 1e-6);
            QVERIFY(a->state.verticalRateMps.has_value());
            QVERIFY(a->state.trackDeg.has_value());
        }
        // Refreshed: a later answer comes.
        QSignalSpy answered(&source, &HciTrafficSource::answered);
        QVERIFY(answered.wait(HciTrafficSource::kRefreshMs * 5));
    }

    // An area without traffic: an empty answer, nothing in the picture.
    void anAreaWithoutTraffic()
    {
        hci::HciSession session;
        hci::HciClient client(&session);
        TrafficPicture picture;
        HciTrafficSource source(&client, &picture);
        session.open(QStringLiteral("127.0.0.1"), m_server->port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QTRY_VERIFY_WITH_TIMEOUT(session.isReady(), 15000);
        QSignalSpy answered(&source, &HciTrafficSource::answered);
        source.setArea(0.5, 0.5, 5000);
        QVERIFY(answered.wait(15000));
        QCOMPARE(source.lastCount(), 0);
        QCOMPARE(picture.count(), 0);
    }
};

QTEST_MAIN(TestHciTraffic)
#include "tst_hcitraffic.moc"
