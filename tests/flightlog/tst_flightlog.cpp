// A recorder on scripted vehicles, then the log read back: telemetry, identities, events and routes;
// damaged and cut-short logs; rotation; export to GPX, KML and CSV parsed back; replay through the
// Vehicle model; comparison with the plan on synthetic flights.
#include "FlightLog.h"
#include "FlightLogExport.h"
#include "FlightLogInfo.h"
#include "FlightLogSchema.h"
#include "FlightLogTestSupport.h"
#include "FlightRecorder.h"
#include "RecordingSettings.h"
#include "ReplayController.h"
#include "ServerHistoryRequest.h"
#include "RouteComparison.h"
#include "Vehicle.h"

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QDateTime>
#include <QSettings>
#include <QSignalSpy>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

using namespace sortie;
using flightlog::FlightLog;
using flightlog::FlightRecorder;
using test::ScriptedLink;
using vehicle::TelemetryField;
using vehicle::Vehicle;

using test::kLegs;
using test::kT0;
using test::recordTwoFlights;

namespace {

int countElements(const QByteArray &xml, const QString &name, QString *error)
{
    QXmlStreamReader r(xml);
    int n = 0;
    while (!r.atEnd()) {
        if (r.readNext() == QXmlStreamReader::StartElement && r.name() == name)
            ++n;
    }
    if (r.hasError())
        *error = r.errorString();
    return n;
}

} // namespace

class TestFlightLog : public QObject
{
    Q_OBJECT

private slots:
    void recordsAndReadsBack()
    {
        QTemporaryDir dir;
        std::vector<test::FlightSample> flown;
        const QString path = recordTwoFlights(dir.path(), &flown);
        QVERIFY(!QFile::exists(path + QStringLiteral("-wal"))); // closed cleanly: one file
        QString error;
        const auto log = FlightLog::open(path, &error);
        QVERIFY2(log, qPrintable(error));
        QVERIFY2(log->stoppedAt().isEmpty(), qPrintable(log->stoppedAt()));
        QCOMPARE(log->vehicles().size(), size_t(2));
        const int a = log->vehicleIndex(QStringLiteral("EMU-101"));
        QVERIFY(a >= 0);
        const FlightLog::Vehicle &va = log->vehicles()[size_t(a)];
        QCOMPARE(va.key, QStringLiteral("VCI:7"));
        QCOMPARE(va.identity.type, QStringLiteral("multicopter"));
        QCOMPARE(va.counts[size_t(TelemetryField::Latitude)], uint64_t(flown.size()));
        QCOMPARE(va.start, kT0);
        QCOMPARE(va.end, flown.back().time);
        // Every position as flown, to its quantum.
        const auto lat = log->series(a, TelemetryField::Latitude);
        QCOMPARE(lat.size(), flown.size());
        for (size_t i = 0; i < flown.size(); ++i) {
            QCOMPARE(lat[i].time, flown[i].time);
            QVERIFY(std::fabs(lat[i].value - flown[i].lat) <= 0.5e-9 / test::kRad * 1.000001); // half the quantum, 1e-9 rad
        }
        QCOMPARE(va.missions.size(), size_t(1));
        QCOMPARE(va.missions.front().items.size(), size_t(2));
        // The mission reads back in degrees, as MissionItem speaks; the log keeps it in radians, as
        // it always has (older logs read the same).
        QVERIFY(std::fabs(va.missions.front().items[1].latitude - kLegs[1].latitude) < 1e-12);
        const QJsonArray stored = QJsonDocument::fromJson(flightlog::schema::missionToJson(va.missions.front().items)).array();
        QVERIFY(std::fabs(stored[1].toArray()[0].toDouble() - kLegs[1].latitude * test::kRad) < 1e-15);
        bool ok = false;
        const auto older = flightlog::schema::missionFromJson(QByteArray("[[0.9939797,0.4206243,20,8]]"), &ok);
        QVERIFY(ok && std::fabs(older[0].latitude - 0.9939797 / test::kRad) < 1e-12 && std::fabs(older[0].longitude - 24.1) < 1e-4);

        QStringList kinds;
        for (const FlightLog::Event &e : log->events())
            kinds << e.kind + QLatin1Char(':') + (e.vehicle >= 0 ? log->vehicles()[size_t(e.vehicle)].name() : QString()) + QLatin1Char(':') + e.text
                         + (e.ok >= 0 ? QStringLiteral(":%1").arg(e.ok) : QString());
        for (const char *expected : {"armed:EMU-101:Armed", "mode:EMU-101:manual", "mode:EMU-101:auto", "link:EMU-102:Lost",
                                     "link:EMU-102:Connected", "command:EMU-101:arm:1", "upload:EMU-101:Route of 2 waypoints",
                                     "session::Recording started", "session::Recording stopped"})
            QVERIFY2(kinds.contains(QString::fromLatin1(expected)), qPrintable(kinds.join(QLatin1Char('\n'))));
        QVERIFY2(std::any_of(kinds.begin(), kinds.end(), [](const QString &k) { return k.startsWith(QLatin1String("command:EMU-102:return home: refused by the test:0")); }),
                 qPrintable(kinds.join(QLatin1Char('\n'))));

        // The state at a time is the last value of each field by then.
        const auto state = log->stateAt(a, flown[100].time + 50);
        const auto latNow = std::find_if(state.begin(), state.end(), [](const auto &u) { return u.field == TelemetryField::Latitude; });
        QVERIFY(latNow != state.end());
        QCOMPARE(latNow->time, flown[100].time);

        const QJsonObject info = flightlog::logInfoJson(*log);
        QCOMPARE(info.value(QStringLiteral("vehicles")).toArray().size(), 2);
        QVERIFY(info.value(QStringLiteral("complete")).toBool());
        QVERIFY(flightlog::logInfoText(*log).contains(QStringLiteral("EMU-102")));
    }

    void aVehicleThatDoesNotSayWhatItIsIsRecorded()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("untyped.sortielog"));
        test::ScriptedLink link(QStringLiteral("9"), QStringLiteral("Sim VCI 1"));
        link.forgetTypeAndAutopilot();
        vehicle::Vehicle v(&link);
        {
            flightlog::FlightRecorder recorder({path, {}, 100});
            QString error;
            QVERIFY2(recorder.start(&error), qPrintable(error));
            recorder.addVehicle(&v);
            const auto flight = test::flyAlong(kLegs, kT0, 20);
            for (const auto &s : flight)
                link.send(test::telemetryAt(s.time, s.lat, s.lon, 20, s.heading, false, 1));
            recorder.stop();
            QVERIFY2(recorder.errorString().isEmpty(), qPrintable(recorder.errorString()));
        }
        QString error;
        const auto log = FlightLog::open(path, &error);
        QVERIFY2(log, qPrintable(error));
        QCOMPARE(log->vehicles().size(), size_t(1));
        QVERIFY(log->vehicles()[0].identity.type.isEmpty());
        QVERIFY(log->vehicles()[0].counts[size_t(TelemetryField::Latitude)] > 0);
    }

    void notALog()
    {
        QTemporaryDir dir;
        QString error;
        QVERIFY(!FlightLog::open(dir.filePath(QStringLiteral("absent.sortielog")), &error));
        QVERIFY2(error.contains(QStringLiteral("no such file")), qPrintable(error));
        QFile text(dir.filePath(QStringLiteral("notes.sortielog")));
        QVERIFY(text.open(QIODevice::WriteOnly));
        text.write("this is not a database\n");
        text.close();
        QVERIFY(!FlightLog::open(text.fileName(), &error));
        QVERIFY2(error.contains(QStringLiteral("not a Sortie flight log")), qPrintable(error));
    }

    void damagedLogsOpenWithWhatIsGood()
    {
        QTemporaryDir dir;
        const QString path = recordTwoFlights(dir.path());
        QString error;
        const auto whole = FlightLog::open(path, &error);
        QVERIFY(whole);
        const size_t allBlocks = whole->vehicles()[0].blocks.size() + whole->vehicles()[1].blocks.size();
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        file.close();

        // Cut short at several points: never a crash, either refused with a reason or read partly
        // with where it stopped.
        int partly = 0;
        for (double keep : {0.2, 0.5, 0.75, 0.9}) {
            const QString cut = dir.filePath(QStringLiteral("cut-%1.sortielog").arg(int(keep * 100)));
            QFile out(cut);
            QVERIFY(out.open(QIODevice::WriteOnly));
            out.write(bytes.left(qsizetype(double(bytes.size()) * keep)));
            out.close();
            const auto log = FlightLog::open(cut, &error);
            if (!log) {
                qInfo("%d %%: %s", int(keep * 100), qPrintable(error));
                QVERIFY(!error.isEmpty());
                continue;
            }
            qInfo("%d %%: %s", int(keep * 100), qPrintable(log->stoppedAt()));
            size_t blocks = 0;
            for (const auto &v : log->vehicles())
                blocks += v.blocks.size();
            QVERIFY(blocks < allBlocks);
            QVERIFY2(!log->stoppedAt().isEmpty(), qPrintable(cut));
            ++partly;
        }
        QVERIFY(partly >= 1);

        // A flipped byte inside a telemetry block: that block is skipped and named, every later one read.
        const QByteArray needle = QByteArray::fromStdString(whole->vehicles()[1].blocks[3].data.substr(0, 24));
        const qsizetype at = bytes.indexOf(needle);
        QVERIFY(at > 0);
        QByteArray corrupt = bytes;
        corrupt[at + 12] = char(corrupt[at + 12] ^ 0x55);
        const QString bad = dir.filePath(QStringLiteral("flipped.sortielog"));
        QFile out(bad);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(corrupt);
        out.close();
        const auto log = FlightLog::open(bad, &error);
        QVERIFY2(log, qPrintable(error));
        QVERIFY2(log->stoppedAt().isEmpty(), qPrintable(log->stoppedAt()));
        QCOMPARE(log->skipped().size(), 1);
        QVERIFY2(log->skipped().front().contains(QStringLiteral("checksum mismatch")), qPrintable(log->skipped().front()));
        QVERIFY2(log->damage().contains(QStringLiteral("skipped")), qPrintable(log->damage()));
        QCOMPARE(log->vehicles()[1].blocks.size(), whole->vehicles()[1].blocks.size() - 1);
        QCOMPARE(log->vehicles()[0].blocks.size(), whole->vehicles()[0].blocks.size());
        // Every block but the flipped one, in order: those after it included (the other vehicle's).
        std::vector<int64_t> expected, read;
        for (size_t i = 0; i < whole->vehicles()[1].blocks.size(); ++i)
            if (i != 3)
                expected.push_back(whole->vehicles()[1].blocks[i].t0);
        for (const auto &block : log->vehicles()[1].blocks)
            read.push_back(block.t0);
        QCOMPARE(read, expected);
    }

    // Issue 36: the reader stopped at the first block naming a vehicle the log does not hold
    // (what a failed commit used to leave), hiding every later sample of every vehicle.
    void aBlockOfAnUnknownVehicleIsSkippedAndNamed()
    {
        QTemporaryDir dir;
        const QString path = recordTwoFlights(dir.path());
        QString error;
        const auto whole = FlightLog::open(path, &error);
        QVERIFY2(whole, qPrintable(error));
        qint64 blockId = -1;
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("damage"));
            db.setDatabaseName(path);
            QVERIFY(db.open());
            QSqlQuery q(db);
            QVERIFY(q.exec(QStringLiteral("SELECT id FROM blocks ORDER BY id LIMIT 1 OFFSET 2")) && q.next());
            blockId = q.value(0).toLongLong();
            QVERIFY(q.exec(QStringLiteral("UPDATE blocks SET vehicle = 999 WHERE id = %1").arg(blockId)));
            q.finish();
            db.close();
        }
        QSqlDatabase::removeDatabase(QStringLiteral("damage"));
        const auto log = FlightLog::open(path, &error);
        QVERIFY2(log, qPrintable(error));
        QVERIFY2(log->stoppedAt().isEmpty(), qPrintable(log->stoppedAt()));
        QCOMPARE(log->skipped().size(), 1);
        const QString named = log->skipped().front();
        QVERIFY2(named.contains(QStringLiteral("block %1 ").arg(blockId)) && named.contains(QStringLiteral("unknown vehicle"))
                     && named.contains(QStringLiteral("999")), qPrintable(named));
        // Every other block is there, to the end of both flights.
        const size_t blocks = log->vehicles()[0].blocks.size() + log->vehicles()[1].blocks.size();
        QCOMPARE(blocks, whole->vehicles()[0].blocks.size() + whole->vehicles()[1].blocks.size() - 1);
        QCOMPARE(log->end(), whole->end());
        QVERIFY(!flightlog::logInfoJson(*log).value(QStringLiteral("complete")).toBool());
        QVERIFY(flightlog::logInfoText(*log).contains(named));
    }

    // Issue 36: two clients started in the same second wrote one file.
    void eachSessionHasAFileOfItsOwn()
    {
        QTemporaryDir dir;
        const QString folder = dir.filePath(QStringLiteral("logs/flights"));
        const QString first = FlightRecorder::sessionPath(folder);
        QVERIFY(QFileInfo(first).isFile()); // claimed at once
        // Whatever second it is now or next, its plain name is taken: the next session's has a
        // suffix of its own, never a part's "-2".
        const QDateTime now = QDateTime::currentDateTimeUtc();
        for (const QDateTime &t : {now, now.addSecs(1)}) {
            QFile taken(QDir(folder).filePath(QStringLiteral("session-%1.sortielog").arg(t.toString(QStringLiteral("yyyyMMdd-HHmmss")))));
            QVERIFY(taken.exists() || taken.open(QIODevice::WriteOnly));
        }
        const QString second = FlightRecorder::sessionPath(folder);
        QVERIFY2(second != first && second.endsWith(QStringLiteral("-c2.sortielog")), qPrintable(second));
        QVERIFY(QFileInfo(second).isFile());
        // Private: the folders it made 0700, the file 0600.
        for (const QString &made : {folder, QFileInfo(folder).path()})
            QCOMPARE(QFileInfo(made).permissions() & (QFileDevice::ReadGroup | QFileDevice::ExeGroup | QFileDevice::ReadOther | QFileDevice::ExeOther),
                     QFileDevice::Permissions());
        QCOMPARE(QFileInfo(second).permissions() & (QFileDevice::ReadGroup | QFileDevice::ReadOther | QFileDevice::WriteGroup | QFileDevice::WriteOther),
                 QFileDevice::Permissions());

        // Two recorders on the two names: two logs, each with its own vehicle.
        ScriptedLink linkA(QStringLiteral("1"), QStringLiteral("EMU-101")), linkB(QStringLiteral("2"), QStringLiteral("EMU-102"));
        Vehicle a(&linkA), b(&linkB);
        FlightRecorder one({first, {}, 100}), two({second, {}, 100});
        QVERIFY(one.start() && two.start());
        one.addVehicle(&a);
        two.addVehicle(&b);
        linkA.send(test::telemetryAt(kT0, 56.97, 24.07, 20, 90, true, 4));
        linkB.send(test::telemetryAt(kT0, 56.98, 24.08, 30, 90, true, 4));
        one.stop();
        two.stop();
        for (const auto &[path, name] : {std::pair{first, QStringLiteral("EMU-101")}, std::pair{second, QStringLiteral("EMU-102")}}) {
            QString error;
            const auto log = FlightLog::open(path, &error);
            QVERIFY2(log, qPrintable(error));
            QCOMPARE(log->vehicles().size(), size_t(1));
            QCOMPARE(log->vehicles()[0].name(), name);
            // -wal and -shm take the log's mode; after a clean close only the log is left.
            QCOMPARE(QFileInfo(path).permissions() & (QFileDevice::ReadGroup | QFileDevice::ReadOther), QFileDevice::Permissions());
        }
    }

    // Pruning never deletes a log a writer has open (its lock), in this process or another
    // (tst_sortielog: two sortie-log recorders).
    void pruningKeepsALogBeingWritten()
    {
        QTemporaryDir dir;
        const QString live = dir.filePath(QStringLiteral("live.sortielog")), done = dir.filePath(QStringLiteral("done.sortielog"));
        flightlog::FlightLogWriter writer(live, {0, 0});
        QString error;
        QVERIFY2(writer.open(&error), qPrintable(error));
        QVERIFY(QFile::exists(live + QStringLiteral(".lock")));
        {
            QFile f(done);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray(64 << 10, 'x'));
        }
        const QString current = dir.filePath(QStringLiteral("current.sortielog"));
        QCOMPARE(flightlog::FlightLogWriter::pruneFolder(dir.path(), 0, current), QStringList{QFileInfo(done).absoluteFilePath()});
        QVERIFY(QFile::exists(live));
        // Another writer cannot take a log being written either.
        flightlog::FlightLogWriter second(live, {0, 0});
        QVERIFY(!second.open(&error));
        QVERIFY2(error.contains(QStringLiteral("another process")), qPrintable(error));
        writer.close();
        QVERIFY(!QFile::exists(live + QStringLiteral(".lock")));
        QCOMPARE(flightlog::FlightLogWriter::pruneFolder(dir.path(), 0, current), QStringList{QFileInfo(live).absoluteFilePath()});
        QVERIFY(!QFile::exists(live));
    }

    void rotatesAndPrunes()
    {
        QTemporaryDir dir;
        const QString path = QDir(dir.path()).filePath(QStringLiteral("small.sortielog"));
        ScriptedLink link(QStringLiteral("1"), QStringLiteral("EMU-101"));
        Vehicle v(&link);
        flightlog::RecordingLimits limits;
        limits.maxFileBytes = 64 << 10;
        limits.maxFolderBytes = 0;
        FlightRecorder recorder({path, limits, 100});
        QVERIFY(recorder.start());
        recorder.addVehicle(&v);
        QSignalSpy rotated(&recorder, &FlightRecorder::pathChanged);
        const auto flight = test::flyAlong(kLegs, kT0, 20);
        for (int round = 0; round < 6; ++round) {
            for (size_t i = 0; i < flight.size(); ++i) {
                const auto &s = flight[i];
                link.send(test::telemetryAt(s.time + round * 600000, s.lat, s.lon, 20, s.heading, true, 4));
                if (i % 100 == 0)
                    recorder.flush();
            }
        }
        recorder.stop();
        const QStringList parts = QDir(dir.path()).entryList({QStringLiteral("*.sortielog")}, QDir::Files, QDir::Name);
        QVERIFY2(parts.size() >= 2, qPrintable(parts.join(QLatin1Char(' '))));
        for (const QString &part : parts) {
            QString error;
            const auto log = FlightLog::open(QDir(dir.path()).filePath(part), &error);
            QVERIFY2(log, qPrintable(error));
            QCOMPARE(log->vehicles().size(), size_t(1)); // every part names its vehicle
            QCOMPARE(log->vehicles()[0].name(), QStringLiteral("EMU-101"));
            QVERIFY(QFileInfo(QDir(dir.path()).filePath(part)).size() < (64 << 10) + (32 << 10));
        }
        // The folder limit removes the oldest first, never the one named to keep.
        const QString newest = QDir(dir.path()).filePath(parts.last());
        const QStringList removed = flightlog::FlightLogWriter::pruneFolder(dir.path(), 70 << 10, newest);
        QVERIFY(!removed.isEmpty());
        QVERIFY(QFile::exists(newest));
    }

    void limitsChangeWhileRecording()
    {
        QTemporaryDir dir;
        // An older session in the folder, for the folder limit to remove.
        const QString old = QDir(dir.path()).filePath(QStringLiteral("session-old.sortielog"));
        {
            QFile f(old);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray(200 << 10, 'x'));
            f.flush();
            QVERIFY(f.setFileTime(QDateTime::currentDateTimeUtc().addDays(-1), QFileDevice::FileModificationTime));
        }
        const QString path = QDir(dir.path()).filePath(QStringLiteral("live.sortielog"));
        ScriptedLink link(QStringLiteral("1"), QStringLiteral("EMU-101"));
        Vehicle v(&link);
        FlightRecorder recorder({path, {}, 100}); // the defaults: 256 MB a log, 4 GB the folder
        QVERIFY(recorder.start());
        recorder.addVehicle(&v);
        const auto flight = test::flyAlong(kLegs, kT0, 20);
        auto fly = [&](size_t from, size_t to) {
            for (size_t i = from; i < to && i < flight.size(); ++i) {
                link.send(test::telemetryAt(flight[i].time, flight[i].lat, flight[i].lon, 20, flight[i].heading, true, 4));
                if (i % 100 == 99)
                    recorder.flush();
            }
        };
        fly(0, flight.size() / 2);
        recorder.flush();
        QTRY_VERIFY(QFileInfo(path).size() + QFileInfo(path + QStringLiteral("-wal")).size() > (16 << 10));
        QCOMPARE(recorder.path(), path);
        QVERIFY(QFile::exists(old));

        // A tiny cap while recording: the log continues in a new part without a restart.
        QSignalSpy rotated(&recorder, &FlightRecorder::pathChanged);
        recorder.setLimits({8 << 10, 0});
        QCOMPARE(recorder.limits().maxFileBytes, qint64(8 << 10));
        QVERIFY(rotated.wait(5000));
        QCOMPARE(QFileInfo(recorder.path()).fileName(), QStringLiteral("live-2.sortielog"));
        // A folder limit: the oldest log goes, the one being written stays.
        recorder.setLimits({0, 1});
        QTRY_VERIFY(!QFile::exists(old));
        QVERIFY(QFile::exists(recorder.path()));
        const QString second = recorder.path();
        fly(flight.size() / 2, flight.size());
        recorder.stop();
        QString error;
        const auto log = FlightLog::open(second, &error);
        QVERIFY2(log, qPrintable(error));
        QCOMPARE(log->vehicles()[0].name(), QStringLiteral("EMU-101"));
        QVERIFY(log->vehicles()[0].counts[size_t(TelemetryField::Latitude)] >= flight.size() / 2 - 1);
    }

    void recordingSettingsCheckSaveAndApply()
    {
        QTemporaryDir dir;
        QSettings storage(QDir(dir.path()).filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
        storage.setValue(QStringLiteral("flightlog/maxFileMB"), 64);
        storage.setValue(QStringLiteral("flightlog/maxFolderMB"), QStringLiteral("lots")); // unreadable: the default
        QCOMPARE(flightlog::RecordingSettings::stored(storage).maxFileBytes, qint64(64) << 20);
        QCOMPARE(flightlog::RecordingSettings::stored(storage).maxFolderBytes, flightlog::RecordingLimits{}.maxFolderBytes);
        FlightRecorder recorder({QDir(dir.path()).filePath(QStringLiteral("logs/a.sortielog")), {}, 100});
        flightlog::RecordingSettings settings(&storage, &recorder);
        QCOMPARE(recorder.limits().maxFileBytes, qint64(64) << 20); // the stored limits, before the start
        QCOMPARE(settings.maxFileMB(), 64);
        QCOMPARE(settings.maxFolderMB(), 4096);
        QVERIFY(recorder.start());
        QCOMPARE(settings.currentLog(), QStringLiteral("a.sortielog"));
        QVERIFY(settings.folder().endsWith(QStringLiteral("logs")));
        settings.refresh();
        QVERIFY2(settings.folderSummary().contains(QStringLiteral("in 1 log")), qPrintable(settings.folderSummary()));
        // Refused, with the reason, and nothing changes.
        QSignalSpy changed(&settings, &flightlog::RecordingSettings::limitsChanged);
        QVERIFY(!settings.apply(100, 50));
        QVERIFY2(settings.errorString().contains(QStringLiteral("at least one whole log")), qPrintable(settings.errorString()));
        QVERIFY(!settings.apply(-1, 0));
        QVERIFY(!settings.errorString().isEmpty());
        QCOMPARE(changed.count(), 0);
        QCOMPARE(storage.value(QStringLiteral("flightlog/maxFileMB")).toInt(), 64);
        // Accepted: saved, and in force in the running recorder.
        QVERIFY(settings.apply(32, 0));
        QVERIFY(settings.errorString().isEmpty());
        QCOMPARE(changed.count(), 1);
        QCOMPARE(recorder.limits().maxFileBytes, qint64(32) << 20);
        QCOMPARE(recorder.limits().maxFolderBytes, qint64(0));
        QCOMPARE(storage.value(QStringLiteral("flightlog/maxFileMB")).toInt(), 32);
        QCOMPARE(storage.value(QStringLiteral("flightlog/maxFolderMB")).toInt(), 0);
        QCOMPARE(flightlog::RecordingSettings::stored(storage).maxFolderBytes, qint64(0)); // 0 stays "no limit"
        recorder.stop();
    }

    void exportsParseBack()
    {
        QTemporaryDir dir;
        std::vector<test::FlightSample> flown;
        const auto log = FlightLog::open(recordTwoFlights(dir.path(), &flown), nullptr);
        QVERIFY(log);
        const int a = log->vehicleIndex(QStringLiteral("EMU-101"));

        QBuffer gpx;
        gpx.open(QIODevice::WriteOnly);
        QVERIFY(flightlog::exportLog(*log, flightlog::ExportFormat::Gpx, {}, &gpx, nullptr));
        QString error;
        QCOMPARE(countElements(gpx.data(), QStringLiteral("trk"), &error), 2);
        QCOMPARE(countElements(gpx.data(), QStringLiteral("trkpt"), &error), int(flown.size() * 2));
        QVERIFY2(error.isEmpty(), qPrintable(error));
        {
            QXmlStreamReader r(gpx.data());
            while (!r.atEnd() && !(r.readNext() == QXmlStreamReader::StartElement && r.name() == QLatin1String("trkpt"))) {}
            QCOMPARE(r.namespaceUri().toString(), QStringLiteral("http://www.topografix.com/GPX/1/1"));
            QVERIFY(std::fabs(r.attributes().value(QStringLiteral("lat")).toDouble() - flown[0].lat) < 1e-7);
            QVERIFY(std::fabs(r.attributes().value(QStringLiteral("lon")).toDouble() - flown[0].lon) < 1e-7);
            r.readNextStartElement();
            QCOMPARE(r.name().toString(), QStringLiteral("ele"));
            QCOMPARE(r.readElementText().toDouble(), 30.0); // AMSL: 10 m ground + 20 m
            r.readNextStartElement();
            QCOMPARE(r.name().toString(), QStringLiteral("time"));
            QCOMPARE(QDateTime::fromString(r.readElementText(), Qt::ISODateWithMs).toMSecsSinceEpoch(), kT0);
        }

        QBuffer kml;
        kml.open(QIODevice::WriteOnly);
        QVERIFY(flightlog::exportLog(*log, flightlog::ExportFormat::Kml, {a}, &kml, nullptr));
        QCOMPARE(countElements(kml.data(), QStringLiteral("Track"), &error), 1);
        QCOMPARE(countElements(kml.data(), QStringLiteral("when"), &error), int(flown.size()));
        QCOMPARE(countElements(kml.data(), QStringLiteral("coord"), &error), int(flown.size()));
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(kml.data().contains("xmlns:gx=\"http://www.google.com/kml/ext/2.2\""));

        QBuffer csv;
        csv.open(QIODevice::WriteOnly);
        QVERIFY(flightlog::exportLog(*log, flightlog::ExportFormat::Csv, {}, &csv, nullptr));
        const QList<QByteArray> lines = csv.data().split('\n');
        const QList<QByteArray> header = lines.first().split(',');
        QCOMPARE(header.mid(0, 2), (QList<QByteArray>{"time", "vehicle"}));
        const int latColumn = int(header.indexOf("latitude [deg]"));
        const int aglColumn = int(header.indexOf("altitudeAgl [m]"));
        QVERIFY(latColumn > 1 && aglColumn > 1);
        QVERIFY(!header.contains("airSpeed [m/s]")); // never sent: no column
        int rowsA = 0;
        for (const QByteArray &line : lines.mid(1)) {
            if (line.isEmpty())
                continue;
            const QList<QByteArray> cells = line.split(',');
            QCOMPARE(cells.size(), header.size());
            if (cells[1] != "EMU-101")
                continue;
            QVERIFY(std::fabs(cells[latColumn].toDouble() - flown[size_t(rowsA)].lat) < 1e-7);
            QCOMPARE(cells[aglColumn].toDouble(), 20.0);
            ++rowsA;
        }
        QCOMPARE(rowsA, int(flown.size()));
    }

    void replayShowsWhatWasRecorded()
    {
        QTemporaryDir dir;
        std::vector<test::FlightSample> flown;
        const QString path = recordTwoFlights(dir.path(), &flown);
        flightlog::ReplayController replay;
        QVERIFY2(replay.open(path), qPrintable(replay.errorString()));
        QCOMPARE(replay.fleet()->count(), 2);
        QCOMPARE(replay.position(), replay.start());
        Vehicle *a = replay.fleet()->vehicleAt(replay.log()->vehicleIndex(QStringLiteral("EMU-101")));
        QVERIFY(a);
        QCOMPARE(a->protocol(), QStringLiteral("Replay")); // never a live vehicle
        QCOMPARE(replay.fleet()->index(0).data(flightlog::ReplayFleet::ReplayRole).toBool(), true);
        // The history is filled with the whole span in the background, for the plots.
        QTRY_VERIFY(replay.isHistoryLoaded());
        QCOMPARE(a->history().series(TelemetryField::Latitude).size(), flown.size());
        QCOMPARE(a->history().series(TelemetryField::Latitude).newest().time, flown.back().time);

        // Scrub anywhere: the vehicle is where it was.
        for (size_t i : {size_t(250), size_t(10), size_t(400), flown.size() - 1}) {
            replay.seek(flown[i].time);
            QVERIFY(std::fabs(a->position().latitude() - flown[i].lat) < 1e-7);
            QVERIFY(std::fabs(a->position().longitude() - flown[i].lon) < 1e-7);
        }
        // Play from the start: every recorded position arrives, in order, equal to the log's.
        replay.seek(replay.start());
        std::vector<vehicle::TelemetrySample> played;
        connect(a->link(), &vehicle::VehicleLink::telemetryReceived, this, [&](const vehicle::TelemetryBatch &batch) {
            for (const auto &u : batch)
                if (u.field == TelemetryField::Latitude)
                    played.push_back({u.time, u.value});
        });
        replay.setSpeed(100);
        QCOMPARE(replay.speed(), 50.0);
        while (replay.position() < replay.end())
            replay.advance(33);
        const auto recorded = replay.log()->series(replay.log()->vehicleIndex(QStringLiteral("EMU-101")), TelemetryField::Latitude);
        QCOMPARE(played.size(), recorded.size() - 1); // all after the first, which the start showed
        for (size_t i = 0; i < played.size(); ++i) {
            QCOMPARE(played[i].time, recorded[i + 1].time);
            QCOMPARE(played[i].value, recorded[i + 1].value);
        }
        // Events: jump to the link loss of EMU-102 and see it lost.
        Vehicle *b = replay.fleet()->vehicleAt(replay.log()->vehicleIndex(QStringLiteral("EMU-102")));
        int lost = -1;
        for (int row = 0; row < replay.events()->rowCount(); ++row) {
            if (replay.events()->index(row).data(flightlog::ReplayEventModel::TextRole) == QStringLiteral("Lost"))
                lost = row;
        }
        QVERIFY(lost >= 0);
        replay.jumpToEvent(lost);
        QCOMPARE(b->linkState(), vehicle::VehicleLink::State::Lost);
        replay.nextEvent();
        QVERIFY(replay.position() > replay.events()->eventAt(lost)->time);
        replay.setProgress(0);
        QCOMPARE(b->linkState(), vehicle::VehicleLink::State::Connected);
        // Commands are refused.
        QSignalSpy result(a, &Vehicle::commandFinished);
        a->arm();
        QVERIFY(result.wait(2000));
        QCOMPARE(result.first().at(1).toBool(), false);
    }

    void replayOpensBeforeTheHistoriesAreDecoded()
    {
        QTemporaryDir dir;
        std::vector<test::FlightSample> flown;
        const QString path = recordTwoFlights(dir.path(), &flown);
        flightlog::ReplayController replay;
        QSignalSpy loaded(&replay, &flightlog::ReplayController::historyLoadedChanged);
        QVERIFY2(replay.open(path), qPrintable(replay.errorString()));
        // The histories arrive through the event loop, which has not run yet: this is the lazy path.
        QVERIFY(!replay.isHistoryLoaded());
        Vehicle *a = replay.fleet()->vehicleAt(replay.log()->vehicleIndex(QStringLiteral("EMU-101")));
        QVERIFY(a);
        QVERIFY(std::fabs(a->position().latitude() - flown.front().lat) < 1e-7);
        QVERIFY(std::fabs(a->position().longitude() - flown.front().lon) < 1e-7);
        QVERIFY(a->history().series(TelemetryField::Latitude).size() < flown.size());
        // Scrub before the histories are there: still where it was.
        replay.seek(flown[300].time);
        QVERIFY(std::fabs(a->position().latitude() - flown[300].lat) < 1e-7);
        // Then the histories: the whole span, the position untouched by them.
        QVERIFY(loaded.wait(5000));
        QVERIFY(replay.isHistoryLoaded());
        const auto &lat = a->history().series(TelemetryField::Latitude);
        QCOMPARE(lat.size(), flown.size());
        QCOMPARE(lat.oldest().time, flown.front().time);
        QCOMPARE(lat.newest().time, flown.back().time);
        QVERIFY(std::fabs(a->position().latitude() - flown[300].lat) < 1e-7);
        QCOMPARE(replay.position(), qint64(flown[300].time));
        // Closed while its worker runs (or has just posted): nothing of it arrives afterwards.
        QVERIFY(replay.open(path));
        QVERIFY(!replay.isHistoryLoaded());
        replay.close(); // cancels the worker and waits for it
        QCoreApplication::processEvents();
        QVERIFY(!replay.isHistoryLoaded());
        // And a log opened again fills again.
        QVERIFY(replay.open(path));
        QTRY_VERIFY(replay.isHistoryLoaded());
        a = replay.fleet()->vehicleAt(replay.log()->vehicleIndex(QStringLiteral("EMU-101")));
        QCOMPARE(a->history().series(TelemetryField::Latitude).size(), flown.size());
    }

    void thinnedSeriesKeepsTheWholeSpan()
    {
        QTemporaryDir dir;
        std::vector<test::FlightSample> flown;
        const QString path = recordTwoFlights(dir.path(), &flown);
        QString error;
        const auto log = FlightLog::open(path, &error);
        QVERIFY2(log, qPrintable(error));
        const int a = log->vehicleIndex(QStringLiteral("EMU-101"));
        const auto all = log->series(a, TelemetryField::Latitude);
        const size_t perField = all.size() / 4;
        const auto thinned = log->thinnedSeries(a, perField);
        QVERIFY(thinned);
        std::vector<vehicle::TelemetryUpdate> lat;
        for (const auto &u : *thinned)
            if (u.field == TelemetryField::Latitude)
                lat.push_back(u);
        QVERIFY(lat.size() <= perField);
        QVERIFY(lat.size() > perField / 2);
        QCOMPARE(lat.front().time, all.front().time);
        int64_t widestGap = 0;
        for (size_t i = 1; i < lat.size(); ++i) {
            QVERIFY(lat[i].time > lat[i - 1].time);
            widestGap = std::max(widestGap, lat[i].time - lat[i - 1].time);
        }
        QVERIFY(all.back().time - lat.back().time <= widestGap); // evenly to the end of the span
        std::atomic_bool cancelled{true};
        QVERIFY(!log->thinnedSeries(a, perField, &cancelled));
    }

    void serverHistoryChoice()
    {
        flightlog::ReplayController replay;
        flightlog::ServerHistoryRequest request(nullptr, &replay);
        const qint64 now = QDateTime(QDate(2026, 11, 24), QTime(12, 0, 29, 250), Qt::UTC).toMSecsSinceEpoch();
        request.setClock([now] { return now; });
        QCOMPARE(request.canFetch(), false);
        QVERIFY2(request.problem().contains(QStringLiteral("connect to a server")), qPrintable(request.problem()));
        request.setVehicles({{QStringLiteral("EMU-101"), 7}, {QStringLiteral("EMU-102"), 9}});
        request.setVehicleIndex(1);
        // Opening the dialog: the last hour up to now (to the second after it), the same vehicle still chosen.
        QSignalSpy changed(&request, &flightlog::ServerHistoryRequest::choiceChanged);
        request.reset();
        QVERIFY(changed.count() >= 1);
        QCOMPARE(request.vehicleNames(), QStringList({QStringLiteral("EMU-101"), QStringLiteral("EMU-102")}));
        QCOMPARE(request.vehicleIndex(), 1);
        QCOMPARE(request.fromText(), QStringLiteral("2026-11-24 11:00:30"));
        QCOMPARE(request.toText(), QStringLiteral("2026-11-24 12:00:30"));
        QVERIFY2(request.canFetch(), qPrintable(request.problem()));
        QCOMPARE(request.range()->first, now + 750 - 3600000);
        QCOMPARE(request.range()->second, now + 750);
        // Times are UTC, to the second or the minute, with a space or a T.
        QCOMPARE(flightlog::ServerHistoryRequest::parseTime(QStringLiteral(" 2026-11-24T11:15 ")), now + 750 - 45 * 60000 - 30000);
        QVERIFY(!flightlog::ServerHistoryRequest::parseTime(QStringLiteral("2026-11-24 25:00")));
        // Each problem named; nothing is sent while there is one.
        request.setFromText(QStringLiteral("yesterday"));
        QVERIFY2(request.problem().contains(QStringLiteral("\"yesterday\" is not a time")), qPrintable(request.problem()));
        QVERIFY(!request.fetch());
        QVERIFY(!request.isBusy());
        request.setFromText(QStringLiteral("2026-11-24 12:00:30"));
        QCOMPARE(request.problem(), QStringLiteral("The start must be before the end."));
        request.setFromText(QStringLiteral("2026-11-24 13:00"));
        request.setToText(QStringLiteral("2026-11-24 14:00"));
        QCOMPARE(request.problem(), QStringLiteral("The start is in the future."));
        request.setFromText(QStringLiteral("2026-11-22 12:00"));
        request.setToText(QStringLiteral("2026-11-24 12:00"));
        QVERIFY2(request.problem().contains(QStringLiteral("24 hours")), qPrintable(request.problem()));
        request.setVehicleIndex(-1);
        QCOMPARE(request.problem(), QStringLiteral("Choose a vehicle."));
        request.chooseLastHour();
        request.setVehicleIndex(0);
        QVERIFY(request.canFetch());
        // No server behind it: the fetch ends at once with the reason, and the replay stays closed.
        QVERIFY(request.fetch());
        QVERIFY(!request.isBusy());
        QVERIFY2(request.errorString().contains(QStringLiteral("not connected")), qPrintable(request.errorString()));
        QVERIFY(!replay.isActive());
        // Opening the dialog again clears the error.
        request.reset();
        QVERIFY(request.errorString().isEmpty());
    }

    void compareFollowsThePlan()
    {
        FlightLog log = syntheticLog(test::flyAlong(kLegs, kT0, 100, 1.0));
        const auto result = flightlog::compareRoute(log, 0, test::routeThrough(kLegs, 20, QStringLiteral("Box")));
        QVERIFY2(result.comparison, qPrintable(result.error));
        const auto &c = *result.comparison;
        QCOMPARE(c.reached, 4);
        QCOMPARE(c.missed, 0);
        QCOMPARE(c.legs.size(), size_t(3));
        // 1 m east of the line: 1 m off the north and south legs, along the east one.
        for (const auto &leg : c.legs) {
            QVERIFY(leg.samples > 10);
            QVERIFY2(leg.maxCrossTrack < 1.1, qPrintable(c.toText()));
            QVERIFY(leg.maxAltitude < 0.01);
        }
        QVERIFY2(std::fabs(c.legs[0].meanCrossTrack - 1.0) < 0.05, qPrintable(c.toText()));
        QVERIFY2(std::fabs(c.legs[2].meanCrossTrack - 1.0) < 0.05, qPrintable(c.toText()));
        QVERIFY(c.toText().contains(QStringLiteral("4 reached, 0 missed")));
        QCOMPARE(c.toJson().value(QStringLiteral("total")).toObject().value(QStringLiteral("missed")).toInt(), 0);
    }

    void compareSentElsewhere()
    {
        // Flies the first leg, then goes 80 m west from the second waypoint (click-and-go).
        const mission::GeoPoint elsewhere = mission::geodesicDirect(kLegs[1], 270, 80).point;
        FlightLog log = syntheticLog(test::flyAlong({kLegs[0], kLegs[1], elsewhere}, kT0, 100));
        const auto result = flightlog::compareRoute(log, 0, test::routeThrough(kLegs, 20, QStringLiteral("Box")));
        QVERIFY2(result.comparison, qPrintable(result.error));
        const auto &c = *result.comparison;
        QCOMPARE(c.reached, 2);
        QCOMPARE(c.missed, 2);
        QVERIFY(!c.waypoints[2].reachedAt && !c.waypoints[3].reachedAt);
        QVERIFY2(c.legs[0].maxCrossTrack < 0.1, qPrintable(c.toText()));
        QVERIFY2(c.legs[1].maxCrossTrack > 70, qPrintable(QString::number(c.legs[1].maxCrossTrack)));
        QVERIFY(c.toText().contains(QStringLiteral("missed")));
    }

    void compareRefusesAnotherVehiclesRoute()
    {
        FlightLog log = syntheticLog(test::flyAlong(kLegs, kT0, 100));
        std::vector<mission::GeoPoint> far;
        for (const auto &p : kLegs)
            far.push_back({p.latitude + 0.1, p.longitude});
        const auto result = flightlog::compareRoute(log, 0, test::routeThrough(far, 20, QStringLiteral("Elsewhere")));
        QVERIFY(!result.comparison);
        QVERIFY2(result.error.contains(QStringLiteral("does not match EMU-101")), qPrintable(result.error));
        const auto absent = flightlog::compareRoute(log, 3, test::routeThrough(kLegs, 20, QStringLiteral("Box")));
        QVERIFY2(absent.error.contains(QStringLiteral("EMU-101")), qPrintable(absent.error));
    }

private:
    static FlightLog syntheticLog(const std::vector<test::FlightSample> &flight)
    {
        flightlog::BlockFields fields;
        FlightLog::Vehicle v;
        v.key = QStringLiteral("HCI:1");
        v.identity.name = QStringLiteral("EMU-101");
        for (size_t i = 0; i < flight.size(); ++i) {
            const auto batch = test::telemetryAt(flight[i].time, flight[i].lat, flight[i].lon, 20, flight[i].heading, true, 4);
            if (fields.empty())
                for (const auto &u : batch)
                    fields.push_back({u.field, {}});
            for (size_t k = 0; k < batch.size(); ++k)
                fields[k].samples.push_back({batch[k].time, batch[k].value});
            if (i % 10 == 9 || i + 1 == flight.size()) {
                if (!v.appendBlock(flightlog::TelemetryBlockCodec::encode(fields)))
                    qFatal("a block the codec made does not read back");
                for (auto &f : fields)
                    f.samples.clear();
            }
        }
        FlightLog log;
        log.addVehicle(v);
        log.finish();
        return log;
    }
};

QTEST_GUILESS_MAIN(TestFlightLog)
#include "tst_flightlog.moc"
