// The sortie-sim program on its own: it starts on a free port, serves a real client, refuses bad
// options with a message naming them, and saves its store when asked to stop.
#include "HciClient.h"
#include "HciReply.h"
#include "HciSession.h"
#include "Messages.pb.h"

#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace sortie;
namespace pb = com::ugcs::ucs::proto;

namespace {

// Starts sortie-sim and returns the port it printed, or 0.
quint16 start(QProcess &process, const QStringList &arguments)
{
    process.start(QStringLiteral(SORTIE_SIM_PROGRAM), arguments);
    if (!process.waitForStarted(10000))
        return 0;
    QDeadlineTimer deadline(15000);
    QByteArray out;
    while (!out.contains('\n') && !deadline.hasExpired() && process.state() == QProcess::Running) {
        process.waitForReadyRead(100);
        out += process.readAllStandardOutput();
    }
    const auto match = QRegularExpression(QStringLiteral("HCI on 127\\.0\\.0\\.1:(\\d+)")).match(QString::fromUtf8(out));
    return match.hasMatch() ? quint16(match.captured(1).toUInt()) : 0;
}

} // namespace

class TestSortieSim : public QObject
{
    Q_OBJECT

private slots:
    void servesAClientAndSavesOnExit()
    {
        QTemporaryDir dir;
        const QString store = dir.filePath(QStringLiteral("store.json"));
        QProcess sim;
        const quint16 port = start(sim, {QStringLiteral("--port"), QStringLiteral("0"), QStringLiteral("--user"),
                                         QStringLiteral("ops:pa55"), QStringLiteral("--store"), store});
        QVERIFY(port > 0);

        hci::HciSession session;
        hci::HciClient client(&session);
        session.open(QStringLiteral("127.0.0.1"), port, QStringLiteral("ops"), QStringLiteral("pa55"));
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), hci::HciSession::State::Ready, 10000);
        hci::HciReply *reply = client.listObjects(hci::HciObjectType::Vehicle);
        reply->setAutoDelete(false);
        QSignalSpy finished(reply, &hci::HciReply::finished);
        QVERIFY(finished.wait());
        QCOMPARE(reply->response<pb::GetObjectListResponse>().objects_size(), 3);
        delete reply;
        session.close();

        sim.terminate();
        QVERIFY(sim.waitForFinished(10000));
        QCOMPARE(sim.exitStatus(), QProcess::NormalExit);
        QCOMPARE(sim.exitCode(), 0);
        QFile saved(store);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QVERIFY(saved.readAll().contains("EMU-102"));
    }

    void refusesBadOptions()
    {
        QProcess sim;
        sim.start(QStringLiteral(SORTIE_SIM_PROGRAM), {QStringLiteral("--port"), QStringLiteral("99999")});
        QVERIFY(sim.waitForFinished(10000));
        QCOMPARE(sim.exitCode(), 2);
        QVERIFY(sim.readAllStandardError().contains("--port"));

        sim.start(QStringLiteral(SORTIE_SIM_PROGRAM), {QStringLiteral("--port"), QStringLiteral("0"), QStringLiteral("--fault-drop"),
                                                       QStringLiteral("NoSuchRequest")});
        QVERIFY(sim.waitForFinished(10000));
        QCOMPARE(sim.exitCode(), 2);
        QVERIFY(sim.readAllStandardError().contains("NoSuchRequest"));
    }
};

QTEST_MAIN(TestSortieSim)
#include "tst_sortiesim.moc"
