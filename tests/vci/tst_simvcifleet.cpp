// sortie-sim's VCI fleet: command-line options, one port (and pty) per vehicle, distinct identities.
#include "SimVciFleet.h"
#include "SimVciListener.h"
#include "SimVciVehicle.h"
#include "VciConnection.h"

#include <QCommandLineParser>
#include <QSignalSpy>
#include <QTcpSocket>
#include <QtTest>

using namespace sortie;

class TstSimVciFleet : public QObject
{
    Q_OBJECT
private slots:
    void optionsAreRead();
    void badOptionsAreRefused();
    void fleetServesEachVehicle();
};

namespace {
bool parse(const QStringList &args, sim::SimVciFleetOptions *options, QString *error)
{
    QCommandLineParser parser;
    options->addTo(parser);
    if (!parser.parse(QStringList{QStringLiteral("sortie-sim")} + args)) {
        *error = parser.errorText();
        return false;
    }
    return options->read(parser, error);
}
} // namespace

void TstSimVciFleet::optionsAreRead()
{
    sim::SimVciFleetOptions o;
    QString error;
    QVERIFY2(parse({"--vci", "3", "--vci-port", "0", "--vci-pty", "--vci-rate", "20", "--vci-time-scale", "4",
                    "--vci-answer-delay", "150", "--vci-malformed-every", "7", "--vci-drop-after", "99", "--vci-content-length"},
                   &o, &error),
             qPrintable(error));
    QCOMPARE(o.count, 3);
    QCOMPARE(o.firstPort, quint16(0));
    QVERIFY(o.pty);
    QCOMPARE(o.vehicle.telemetryRate, 20.0);
    QCOMPARE(o.vehicle.timeScale, 4.0);
    QCOMPARE(o.vehicle.answerDelayMs, 150);
    QCOMPARE(o.vehicle.malformedEvery, 7);
    QCOMPARE(o.vehicle.dropAfter, 99);
    QVERIFY(o.vehicle.framing == vci::VciFraming::ContentLength);
    sim::SimVciFleetOptions defaults;
    QVERIFY(parse({}, &defaults, &error));
    QCOMPARE(defaults.count, 0);
    QCOMPARE(defaults.firstPort, quint16(5760));
}

void TstSimVciFleet::badOptionsAreRefused()
{
    sim::SimVciFleetOptions o;
    QString error;
    QVERIFY(!parse({"--vci", "many"}, &o, &error));
    QVERIFY(error.contains(QLatin1String("--vci")));
    QVERIFY(!parse({"--vci", "2", "--vci-port", "65535"}, &o, &error));
    QVERIFY(!parse({"--vci-rate", "0"}, &o, &error));
}

void TstSimVciFleet::fleetServesEachVehicle()
{
    sim::SimVciFleetOptions o;
    o.count = 3;
    o.firstPort = 0;
    o.pty = true;
    sim::SimVciFleet fleet(o);
    QString error;
    QVERIFY2(fleet.start(&error), qPrintable(error));
    const QStringList lines = fleet.describe();
    QCOMPARE(lines.size(), 3);
    QVERIFY(lines[1].startsWith(QLatin1String("vci-2 tcp://127.0.0.1:")));
    QVERIFY(lines[1].contains(QLatin1String(" serial:/dev/")));
    QVERIFY(fleet.listeners()[0]->port() != fleet.listeners()[2]->port());
    QVERIFY(fleet.vehicles()[0]->model().state().latitude != fleet.vehicles()[1]->model().state().latitude);

    QTcpSocket socket;
    socket.connectToHost(QHostAddress::LocalHost, fleet.listeners()[1]->port());
    QVERIFY(socket.waitForConnected(5000));
    vci::VciConnection conn;
    conn.setDevice(&socket);
    nlohmann::json id;
    conn.get(QStringLiteral("/vehicle"), nullptr, [&](const vci::VciResult &r) { id = r.body["id"]; });
    QTRY_COMPARE(id, nlohmann::json("vci-2"));
}

QTEST_GUILESS_MAIN(TstSimVciFleet)
#include "tst_simvcifleet.moc"
