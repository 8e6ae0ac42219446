// Real crashes: a helper process edits a route with RouteAutosave running and is killed with
// SIGKILL. Recovery in this process then finds its autosave (the helper's lock is stale), lists
// exactly the edits it made and restores a route equal to the edited one. Killing it in the middle
// of a burst of autosaves always leaves a file that parses. While the helper lives, its autosave
// is not offered.
#include "AutosaveRecord.h"
#include "AutosaveRecovery.h"
#include "AutosaveTestRoute.h"
#include "HciOrigin.h"
#include "RouteDiff.h"

#include <QFile>
#include <QProcess>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace sortie;

namespace {

void killHard(QProcess &helper)
{
    helper.kill(); // SIGKILL: no destructor, no cleanup, the lock file stays behind
    helper.waitForFinished(10000);
}

// Starts the helper and waits for a line starting with `ready`; the line, or empty on failure.
QString startHelper(QProcess &helper, const QStringList &arguments, const QByteArray &ready)
{
    helper.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    helper.start(QStringLiteral(SORTIE_AUTOSAVE_HELPER), arguments);
    if (!helper.waitForStarted(10000))
        return {};
    QByteArray out;
    QDeadlineTimer deadline(15000);
    while (!out.contains('\n') && helper.state() == QProcess::Running && !deadline.hasExpired())
        if (helper.waitForReadyRead(1000))
            out += helper.readAll();
    if (!out.contains('\n'))
        killHard(helper);
    const QString line = QString::fromUtf8(out.left(out.indexOf('\n')));
    return line.startsWith(QString::fromLatin1(ready)) ? line : QString();
}

} // namespace

class TestAutosaveCrash : public QObject
{
    Q_OBJECT

private slots:
    void recoversTheEditsOfAKilledProcess()
    {
        QTemporaryDir dir;
        const QString expectedFile = QDir(dir.path()).filePath(QStringLiteral("expected.sortie"));
        const QString autosaves = QDir(dir.path()).filePath(QStringLiteral("autosave"));
        QProcess helper;
        const QString line = startHelper(helper, {autosaves, QStringLiteral("edit"), expectedFile}, "AUTOSAVED ");
        QVERIFY2(!line.isEmpty(), "the helper did not autosave");
        const QString file = line.mid(10);

        // While it lives, its autosave is not ours to offer.
        {
            client::RouteDocument doc;
            client::AutosaveRecovery recovery(&doc, autosaves);
            QVERIFY(!recovery.isAvailable());
        }
        killHard(helper);
        QCOMPARE(helper.exitStatus(), QProcess::CrashExit);
        QVERIFY(QFile::exists(client::AutosaveDirectory(autosaves).lockPath(1))); // stale, not removed

        client::RouteDocument doc;
        client::AutosaveRecovery recovery(&doc, autosaves);
        QVERIFY2(recovery.isAvailable(), qPrintable(recovery.message()));
        QCOMPARE(recovery.fileName(), file);
        const double altitude = std::get<mission::Waypoint>(test::serverRoute().segments[2]).altitude;
        QCOMPARE(recovery.changes(), (QStringList{QStringLiteral("WP 2 moved 33 m"),
                                                  QStringLiteral("altitude of WP 3 %1 → 100 m").arg(altitude),
                                                  QStringLiteral("WP 13 added")}));
        recovery.setSession(QStringLiteral("127.0.0.1:3334"), QStringLiteral("admin")); // where the helper's route belongs
        QVERIFY(recovery.restore());

        auto expected = mission::formats::loadMission(expectedFile);
        QVERIFY2(expected, expected ? "" : qPrintable(expected.error().toString()));
        QVERIFY2(doc.route() == expected->mission.routes.front(),
                 qPrintable(mission::RouteDiff::compare(expected->mission.routes.front(), doc.route()).summary()));
        QCOMPARE(hciRoute(doc.route().origin)->id(), 42);
        QCOMPARE(hciRoute(doc.route().origin)->version(), 3);
        QVERIFY(doc.isModified());
    }

    void aKillDuringABurstOfWritesLeavesAFileThatParses()
    {
        for (int round = 0; round < 5; ++round) {
            QTemporaryDir dir;
            QProcess helper;
            QVERIFY2(!startHelper(helper, {dir.path(), QStringLiteral("burst")}, "BURSTING").isEmpty(), "the helper did not write");
            // Let it write for a while, a different while each round, then kill it mid-stride.
            QTest::qWait(20 + QRandomGenerator::global()->bounded(200));
            killHard(helper);

            const QString path = client::AutosaveDirectory(dir.path()).filePath(1);
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const auto record = client::decodeAutosave(f.readAll());
            QVERIFY2(record, record ? "" : qPrintable(record.error().toString()));
            QVERIFY(record->working.segments.size() > 12);
            QCOMPARE(record->baseline.segments.size(), size_t(12));
            client::RouteDocument doc;
            client::AutosaveRecovery recovery(&doc, dir.path());
            QVERIFY2(recovery.isAvailable(), qPrintable(recovery.message()));
            recovery.setSession(QStringLiteral("127.0.0.1:3334"), QStringLiteral("admin"));
            QVERIFY(recovery.restore());
            QCOMPARE(doc.model()->count(), int(record->working.segments.size()));
        }
    }
};

QTEST_GUILESS_MAIN(TestAutosaveCrash)
#include "tst_autosavecrash.moc"
