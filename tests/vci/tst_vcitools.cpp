// The programs: sortie-sim serving VCI vehicles on TCP and a pty (its printed endpoints work), and
// sortie-dump turning a captured VCI stream into JSON lines.
#include "VciConnection.h"
#include "VciEndpoint.h"
#include "VciTransport.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryFile>
#include <QtTest>

using nlohmann::json;
using namespace sortie::vci;

class TstVciTools : public QObject
{
    Q_OBJECT
private slots:
    void simServesVciVehicles();
    void dumpDecodesAVciCapture();
    void dumpRecognisesVciWithoutTheFlag();
};

namespace {

json identityAt(const QString &url)
{
    VciTransport transport(*VciEndpoint::parse(url));
    VciConnection conn;
    QObject::connect(&transport, &VciTransport::opened, &conn, [&](QIODevice *d) { conn.setDevice(d); });
    json id;
    QObject::connect(&conn, &VciConnection::attached, &conn, [&] {
        conn.get(QStringLiteral("/vehicle"), nullptr, [&](const VciResult &r) { id = r.body; });
    });
    transport.open();
    QDeadlineTimer deadline(10000);
    while (id.is_null() && !deadline.hasExpired())
        QTest::qWait(10);
    conn.setDevice(nullptr);
    return id;
}

QList<json> dump(const QStringList &args, const QByteArray &input)
{
    QProcess p;
    p.start(QStringLiteral(SORTIE_DUMP), args);
    if (!p.waitForStarted())
        return {};
    p.write(input);
    p.closeWriteChannel();
    p.waitForFinished(10000);
    QList<json> lines;
    for (const QByteArray &line : p.readAllStandardOutput().split('\n')) {
        if (!line.isEmpty())
            lines << json::parse(line.toStdString());
    }
    return lines;
}

const QByteArray kCapture = "SUBSCRIBE /telemetry/gps VCI/1.0\r\n\r\n"
                            "VCI/1.0 200 OK\r\n\r\n"
                            "NOTIFY /telemetry/gps VCI/1.0\r\nContent-Type: application/json\r\n\r\n{\"fix\":3,\"satellites\":14}"
                            "PUT /state/armed VCI/1.0\r\nContent-Type: application/json\r\nContent-Length: 4\r\n\r\ntrue"
                            "BREW /coffee VCI/1.0\r\n\r\n"
                            "VCI/1.0 400 Bad Request\r\nContent-Type: application/json\r\n\r\n{\"error\":\"no 3D GPS fix\"}";

} // namespace

void TstVciTools::simServesVciVehicles()
{
    QProcess sim;
    sim.start(QStringLiteral(SORTIE_SIM), {"--port", "0", "--hci-vehicles", "0", "--vci", "2", "--vci-port", "0", "--vci-pty"});
    QVERIFY(sim.waitForStarted());
    QStringList urls;
    const QRegularExpression line(QStringLiteral("^sortie-sim: VCI (vci-\\d) (tcp://\\S+) (serial:\\S+)$"));
    QDeadlineTimer deadline(15000);
    QByteArray out;
    while (urls.size() < 4 && !deadline.hasExpired()) {
        sim.waitForReadyRead(100);
        out += sim.readAllStandardOutput();
        urls.clear();
        for (const QByteArray &l : out.split('\n')) {
            const auto m = line.match(QString::fromUtf8(l));
            if (m.hasMatch())
                urls << m.captured(2) << m.captured(3);
        }
    }
    QVERIFY2(urls.size() == 4, out.constData());
    QCOMPARE(identityAt(urls[0])["id"], json("vci-1"));
    QCOMPARE(identityAt(urls[3])["id"], json("vci-2")); // over its pseudo-terminal
    sim.terminate();
    QVERIFY(sim.waitForFinished(10000));
}

void TstVciTools::dumpDecodesAVciCapture()
{
    const QList<json> lines = dump({QStringLiteral("--vci")}, kCapture);
    QCOMPARE(lines.size(), 6);
    QCOMPARE(lines[0]["verb"], json("SUBSCRIBE"));
    QCOMPARE(lines[0]["offset"], json(0));
    QCOMPARE(lines[1]["status"], json(200));
    QCOMPARE(lines[2]["body"]["satellites"], json(14));
    QCOMPARE(lines[2]["headers"][0], json::array({"Content-Type", "application/json"}));
    QCOMPARE(lines[3]["body"], json(true));
    QCOMPARE(lines[4]["kind"], json("error"));
    QCOMPARE(lines[4]["error"], json("unknown verb"));
    QCOMPARE(lines[4]["reply"], json(501));
    QCOMPARE(lines[5]["reason"], json("Bad Request"));
    QCOMPARE(lines[5]["body"]["error"], json("no 3D GPS fix"));
    QCOMPARE(lines[5]["offset"], json(kCapture.indexOf("VCI/1.0 400")));
}

void TstVciTools::dumpRecognisesVciWithoutTheFlag()
{
    const QList<json> lines = dump({}, kCapture + "NOTIFY /cut VCI/1.0\r\nContent-Type: application/json\r\n\r\n[1,");
    QCOMPARE(lines.size(), 7);
    QCOMPARE(lines[6]["error"], json("truncated"));
}

QTEST_GUILESS_MAIN(TstVciTools)
#include "tst_vcitools.moc"
