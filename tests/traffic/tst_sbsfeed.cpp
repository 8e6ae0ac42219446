// The SBS-1 feed over TCP on 127.0.0.1: against sortie-sim's --sbs-port (the simulated traffic
// arrives whole: call sign, position, velocity), through the simulator going away and coming back
// (the feed waits, says why, and reconnects), and against a receiver sending garbage among good
// lines (each bad line named and skipped, the good ones believed).
#include "FreePort.h"
#include "SbsFeed.h"
#include "SimSbsServer.h"
#include "SimTraffic.h"
#include "TrafficPicture.h"

#include <QDeadlineTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

#include <cmath>

using namespace sortie;
using namespace sortie::traffic;

namespace {

// Starts sortie-sim with these arguments and returns the SBS port it printed, or 0.
quint16 startSim(QProcess &process, const QStringList &arguments)
{
    process.start(QStringLiteral(SORTIE_SIM_PROGRAM), QStringList{QStringLiteral("--port"), QStringLiteral("0")} + arguments);
    if (!process.waitForStarted(10000))
        return 0;
    QDeadlineTimer deadline(15000);
    QByteArray out;
    const QRegularExpression sbs(QStringLiteral("SBS-1 traffic on 127\\.0\\.0\\.1:(\\d+)"));
    while (!deadline.hasExpired() && process.state() == QProcess::Running) {
        process.waitForReadyRead(100);
        out += process.readAllStandardOutput();
        const auto match = sbs.match(QString::fromUtf8(out));
        if (match.hasMatch())
            return quint16(match.captured(1).toUInt());
    }
    return 0;
}

double metresFromCentre(const TrafficReport &s)
{
    const double north = (*s.latitude - sim::SimTraffic::kCentreLatitude) * 111195.0;
    const double east = (*s.longitude - sim::SimTraffic::kCentreLongitude) * 111195.0 * std::cos(sim::SimTraffic::kCentreLatitude * M_PI / 180);
    return std::hypot(north, east);
}

} // namespace

class TestSbsFeed : public QObject
{
    Q_OBJECT

private slots:
    void sortieSimServesItsTraffic()
    {
        QProcess sim;
        const quint16 port = startSim(sim, {QStringLiteral("--sbs-port"), QStringLiteral("0")});
        QVERIFY2(port > 0, qPrintable(sim.readAllStandardError()));
        TrafficPicture picture;
        SbsFeed feed(&picture);
        QVERIFY(feed.setAddress(QStringLiteral("127.0.0.1:%1").arg(port)));
        QTRY_COMPARE_WITH_TIMEOUT(feed.state(), SbsFeed::State::Connected, 10000);
        // Every aircraft with its call sign, position, altitude and velocity (MSG 1, 3 and 4 merged).
        const auto complete = [&picture] {
            int n = 0;
            for (const TrafficAircraft &a : picture.aircraft())
                n += a.state.callsign && a.state.latitude && a.state.altitudeM && velocityOf(a.state) && velocityOf(a.state)->up ? 1 : 0;
            return n;
        };
        QTRY_COMPARE_WITH_TIMEOUT(complete(), 3, 10000);
        QStringList callsigns;
        for (const TrafficAircraft &a : picture.aircraft()) {
            callsigns << *a.state.callsign;
            QCOMPARE(a.state.altitudeReference, AltitudeReference::Barometric);
            QCOMPARE(a.state.source, TrafficSource::Receiver);
            const double r = metresFromCentre(a.state); // on its orbit around the demo area
            QVERIFY2(r > 850 && r < 4050, qPrintable(QString::number(r)));
        }
        callsigns.sort();
        QCOMPARE(callsigns, (QStringList{QStringLiteral("AFR64K"), QStringLiteral("BTI7TR"), QStringLiteral("YLHEL1")}));
        QCOMPARE(feed.droppedLines(), 0);
        QVERIFY(feed.messages() >= 9);
        sim.kill();
        sim.waitForFinished();
    }

    // The simulator killed: the feed waits and says why; started again on the same port: it is back.
    void reconnectsAfterTheReceiverWentAway()
    {
        const quint16 port = test::freePort();
        QProcess sim;
        QCOMPARE(startSim(sim, {QStringLiteral("--sbs-port"), QString::number(port)}), port);
        TrafficPicture picture;
        SbsFeed feed(&picture);
        feed.setAddress(QStringLiteral("127.0.0.1:%1").arg(port));
        QTRY_COMPARE_WITH_TIMEOUT(feed.state(), SbsFeed::State::Connected, 10000);
        sim.kill();
        sim.waitForFinished();
        QTRY_COMPARE_WITH_TIMEOUT(feed.state(), SbsFeed::State::Waiting, 10000);
        QVERIFY(!feed.error().isEmpty());
        QVERIFY2(feed.statusText().contains(QStringLiteral("again in")), qPrintable(feed.statusText()));
        QProcess again;
        QCOMPARE(startSim(again, {QStringLiteral("--sbs-port"), QString::number(port)}), port);
        QTRY_COMPARE_WITH_TIMEOUT(feed.state(), SbsFeed::State::Connected, 40000);
        QVERIFY(feed.error().isEmpty());
        again.kill();
        again.waitForFinished();
    }

    // Nobody listening: each failed attempt doubles the wait, up to the limit.
    void backsOffWhileNobodyListens()
    {
        TrafficPicture picture;
        SbsFeed feed(&picture);
        feed.setAddress(QStringLiteral("127.0.0.1:%1").arg(test::freePort()));
        QTRY_COMPARE_WITH_TIMEOUT(feed.state(), SbsFeed::State::Waiting, 10000);
        QCOMPARE(feed.retryDelayMs(), 2 * SbsFeed::kFirstRetryMs); // the next wait after this one
        QTRY_COMPARE_WITH_TIMEOUT(feed.retryDelayMs(), 4 * SbsFeed::kFirstRetryMs, 10000);
        QVERIFY(!feed.setAddress(QStringLiteral("no port here")));
        QCOMPARE(feed.state(), SbsFeed::State::Off);
        QVERIFY(feed.statusText().contains(QStringLiteral("not host:port")));
        QVERIFY(feed.setAddress(QString()));
        QCOMPARE(feed.statusText(), QStringLiteral("receiver off"));
    }

    // A receiver sending garbage among good lines: each bad line is counted and named, nothing of
    // it believed, and the good lines around it are.
    void garbageIsNamedAndSkipped()
    {
        QTcpServer receiver;
        QVERIFY(receiver.listen(QHostAddress::LocalHost, 0));
        TrafficPicture picture;
        SbsFeed feed(&picture);
        feed.setAddress(QStringLiteral("127.0.0.1:%1").arg(receiver.serverPort()));
        QVERIFY(receiver.waitForNewConnection(10000));
        QTcpSocket *socket = receiver.nextPendingConnection();
        const QByteArray time = "2026/11/26,18:44:00.123,2026/11/26,18:44:00.125";
        socket->write("MSG,3,1,1,502C11,1," + time + ",,820,,,56.97650,24.07600,,,0,0,0,0\r\n");
        socket->write("MSG,3,1,1,502C99,1," + time + ",,820,,,156.0,24.07600,,,0,0,0,0\r\n");
        socket->write(QByteArray(3000, '\x07') + "\n");
        socket->write("MSG,1,1,1,502C11,1," + time + ",YLHEL1,,,,,,,,,,,\r\n");
        QTRY_COMPARE_WITH_TIMEOUT(feed.messages(), 2, 10000);
        QCOMPARE(feed.droppedLines(), 2);
        QCOMPARE(feed.lastDropped(), QStringLiteral("line 3: longer than 512 bytes: skipped to the next newline"));
        QCOMPARE(picture.count(), 1); // 502C99 and its impossible latitude were never believed
        QCOMPARE(picture.aircraft()[0].state.callsign.value(), QStringLiteral("YLHEL1"));
        QCOMPARE(feed.state(), SbsFeed::State::Connected);
    }

    // --sbs-port is in the help; a value that is no port is refused, naming the option.
    void sortieSimOption()
    {
        QProcess sim;
        sim.start(QStringLiteral(SORTIE_SIM_PROGRAM), {QStringLiteral("--help")});
        QVERIFY(sim.waitForFinished(15000));
        QVERIFY(sim.readAllStandardOutput().contains("--sbs-port"));
        sim.start(QStringLiteral(SORTIE_SIM_PROGRAM), {QStringLiteral("--port"), QStringLiteral("0"), QStringLiteral("--sbs-port"), QStringLiteral("70000")});
        QVERIFY(sim.waitForFinished(15000));
        QCOMPARE(sim.exitCode(), 2);
        QVERIFY(sim.readAllStandardError().contains("--sbs-port: expected a port from 0 to 65535, got '70000'"));
    }

    // In-process (as sortie --demo runs it): a new client gets every aircraft at once.
    void aNewClientGetsEveryAircraftAtOnce()
    {
        sim::SimTraffic traffic;
        sim::SimSbsServer server(traffic);
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        TrafficPicture picture;
        SbsFeed feed(&picture);
        feed.setAddress(QStringLiteral("127.0.0.1:%1").arg(server.port()));
        QTRY_COMPARE_WITH_TIMEOUT(picture.count(), 3, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(server.clientCount(), 1, 10000);
    }
};

QTEST_MAIN(TestSbsFeed)
#include "tst_sbsfeed.moc"
