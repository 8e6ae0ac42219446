// sortie-log against the simulator over loopback, as separate processes: two recorders follow the
// server while EMU-101 flies its route and EMU-102 is sent elsewhere mid-route (click-and-go). One
// recorder is killed with SIGKILL mid-flight and its log reopens with at most the last second
// missing; the other is stopped with SIGTERM and closes its log. Then info, export (parsed back) and
// compare run on the log as an operator would run them.
#include "ConnectionController.h"
#include "FleetRecording.h"
#include "FlightLog.h"
#include "FlightLogWriter.h"
#include "FlightRecorder.h"
#include "FlightLogTestSupport.h"
#include "SortieLogRun.h"
#include "HciClient.h"
#include "HciServer.h"
#include "HciSession.h"
#include "HciVehicleLink.h"
#include "Messages.pb.h"
#include "MissionFiles.h"
#include "ReplayController.h"
#include "ServerHistory.h"
#include "SimWorld.h"
#include "TestCertificates.h"
#include "TlsServerIdentity.h"
#include "VehicleFleet.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

using namespace sortie;
using flightlog::FlightLog;
using vehicle::Vehicle;
using test::Run;
using test::sortieLog;

namespace {

struct Sim
{
    Sim()
        : world(config())
        , server(world)
    {
        server.setUploadStepMs(5);
        if (!server.listen(QHostAddress::LocalHost, 0))
            qFatal("cannot start the simulator: %s", qPrintable(server.errorString()));
    }
    static sim::SimWorld::Config config()
    {
        sim::SimWorld::Config c;
        c.telemetryRateHz = 20;
        c.users = {{0, QStringLiteral("admin"), QStringLiteral("admin"), true}};
        return c;
    }
    QString address() const { return QStringLiteral("127.0.0.1:%1").arg(server.port()); }
    sim::SimWorld world;
    sim::HciServer server;
};

// A route of four waypoints around a start point, 12 m above home: 20 m north, 30 m east, 20 m south.
std::vector<mission::GeoPoint> boxFrom(const QGeoCoordinate &home)
{
    const mission::GeoPoint h{home.latitude(), home.longitude()};
    const mission::GeoPoint a = mission::geodesicDirect(h, 0, 20).point;
    const mission::GeoPoint b = mission::geodesicDirect(a, 90, 30).point;
    const mission::GeoPoint c = mission::geodesicDirect(b, 180, 20).point;
    const mission::GeoPoint d = mission::geodesicDirect(c, 270, 15).point;
    return {a, b, c, d};
}

// The box as a route of waypoints 12 m above the ground, flown at 8 m/s.
mission::Route routeOf(const std::vector<mission::GeoPoint> &points)
{
    mission::Route route;
    route.settings.name = QStringLiteral("box");
    for (const auto &p : points) {
        mission::Waypoint w;
        w.position = p;
        w.altitude = 12;
        w.altitudeType = mission::AltitudeType::Agl;
        w.speed = 8;
        route.segments.push_back(w);
    }
    return route;
}

// Metres from where a vehicle is now to a point (HCI reports no waypoint index: progress is position).
double metresTo(const Vehicle *v, const mission::GeoPoint &p)
{
    const QGeoCoordinate at = v->position();
    return at.isValid() ? mission::geodesicDistance({at.latitude(), at.longitude()}, p) : 1e9;
}

QString saveRoute(const QString &path, const std::vector<mission::GeoPoint> &points, const QString &name)
{
    mission::Mission m;
    m.name = name;
    m.routes.push_back(test::routeThrough(points, 12, name));
    m.routes.back().settings.safeAltitude = 5;
    const auto saved = mission::formats::saveMission(m, path, {0, mission::ValidationOverride::AcceptErrors, {}});
    if (!saved)
        qFatal("%s", qPrintable(saved.error().toString()));
    return path;
}

} // namespace

class TestSortieLog : public QObject
{
    Q_OBJECT

private slots:
    // Over TLS with the server's certificate pinned: logged in, recorded, closed. A pin the server
    // does not match is refused with both fingerprints, and nothing is recorded. A plain connection
    // to a server that is not this computer is refused before anything is sent, unless the command
    // line allows it.
    void recordsOverTlsAndRefusesCleartext()
    {
        QTemporaryDir dir;
        test::TestCertificates maker(dir.path());
        const auto a = maker.selfSigned(QStringLiteral("a"));
        QVERIFY2(a, qPrintable(maker.error()));
        const auto b = maker.selfSigned(QStringLiteral("b"));
        QVERIFY2(b, qPrintable(maker.error()));
        Sim sim;
        sim.server.close();
        QString error;
        sim.server.setTls(tls::loadServerIdentity(a->certificate, a->key, &error));
        QVERIFY2(sim.server.listen(QHostAddress::LocalHost, 0), qPrintable(sim.server.errorString()));
        const QString secure = QStringLiteral("tls://") + sim.address();
        const QStringList login{QStringLiteral("record"), QStringLiteral("--server"), secure, QStringLiteral("--user"), QStringLiteral("admin"),
                                QStringLiteral("--seconds"), QStringLiteral("2")};
        qputenv("SORTIE_PASSWORD", "admin");

        // The process runs while this thread serves the simulator: wait with the event loop turning.
        auto recordWith = [&](const QStringList &extra, const QString &log) {
            QProcess p;
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
            p.setProcessEnvironment(env);
            p.start(QStringLiteral(SORTIE_LOG_PROGRAM), login + extra + QStringList{log});
            Run r;
            if (!QTest::qWaitFor([&] { return p.state() == QProcess::NotRunning; }, 60000))
                return r;
            r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
            r.out = p.readAllStandardOutput();
            r.err = p.readAllStandardError();
            return r;
        };
        const Run pinned = recordWith({QStringLiteral("--server-pin"), a->certificate}, dir.filePath(QStringLiteral("tls.sortielog")));
        QVERIFY2(pinned.exitCode == 0, pinned.err.constData());
        QVERIFY2(pinned.out.contains("the certificate pinned for") && pinned.out.contains(a->fingerprint.toLatin1()), pinned.out.constData());
        QVERIFY2(pinned.out.contains("logged in to"), pinned.out.constData());
        QString openError;
        const auto log = FlightLog::open(dir.filePath(QStringLiteral("tls.sortielog")), &openError);
        QVERIFY2(log, qPrintable(openError));
        QCOMPARE(int(log->vehicles().size()), 3);

        const Run wrong = recordWith({QStringLiteral("--server-pin"), b->fingerprint}, dir.filePath(QStringLiteral("wrong.sortielog")));
        QCOMPARE(wrong.exitCode, 1);
        QVERIFY2(wrong.err.contains(a->fingerprint.toLatin1()) && wrong.err.contains(b->fingerprint.toLatin1()), wrong.err.constData());
        QVERIFY2(!wrong.out.contains("logged in"), wrong.out.constData());

        // 192.0.2.1 (TEST-NET-1) is not this computer: refused before a connection is tried.
        const Run clear = sortieLog({QStringLiteral("record"), QStringLiteral("--server"), QStringLiteral("192.0.2.1:3334"), QStringLiteral("--user"),
                                     QStringLiteral("admin"), dir.filePath(QStringLiteral("clear.sortielog"))},
                                    dir.filePath(QStringLiteral("config")));
        QCOMPARE(clear.exitCode, 1);
        QVERIFY2(clear.err.contains("the password would cross the network in clear") && clear.err.contains("--allow-cleartext"), clear.err.constData());
        const Run badPin = sortieLog({QStringLiteral("record"), QStringLiteral("--server"), secure, QStringLiteral("--user"), QStringLiteral("admin"),
                                      QStringLiteral("--server-pin"), QStringLiteral("12:34"), dir.filePath(QStringLiteral("bad.sortielog"))},
                                     dir.filePath(QStringLiteral("config")));
        QCOMPARE(badPin.exitCode, 2);
        QVERIFY2(badPin.err.contains("--server-pin: '12:34' is neither a SHA-256 fingerprint"), badPin.err.constData());
        qunsetenv("SORTIE_PASSWORD");
    }

    void recordsFlightsSurvivesKillAndCompares()
    {
        Sim sim;
        QTemporaryDir dir;
        const QString passwordFile = dir.filePath(QStringLiteral("password"));
        {
            QFile f(passwordFile);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("admin\n");
        }
        const QString cleanLog = dir.filePath(QStringLiteral("clean.sortielog"));
        const QString killedLog = dir.filePath(QStringLiteral("killed.sortielog"));
        QProcess clean, killed;
        QByteArray cleanOut, killedOut;
        connect(&clean, &QProcess::readyReadStandardOutput, this, [&] { cleanOut += clean.readAllStandardOutput(); });
        connect(&killed, &QProcess::readyReadStandardOutput, this, [&] { killedOut += killed.readAllStandardOutput(); });
        const QStringList common{QStringLiteral("record"), QStringLiteral("--server"), sim.address(), QStringLiteral("--user"),
                                 QStringLiteral("admin"), QStringLiteral("--password-file"), passwordFile};
        clean.setProcessChannelMode(QProcess::SeparateChannels);
        clean.start(QStringLiteral(SORTIE_LOG_PROGRAM), common + QStringList{QStringLiteral("--seconds"), QStringLiteral("300"), cleanLog});
        killed.start(QStringLiteral(SORTIE_LOG_PROGRAM), common + QStringList{killedLog});
        QTRY_VERIFY_WITH_TIMEOUT(cleanOut.contains("logged in") && killedOut.contains("logged in"), 15000);
        QTRY_VERIFY_WITH_TIMEOUT(cleanOut.contains("3 vehicles") && killedOut.contains("3 vehicles"), 15000);

        // Pruning the folder to nothing while both record: an old log goes, neither live one (each
        // recorder holds its log's lock).
        const QString old = dir.filePath(QStringLiteral("old.sortielog"));
        {
            QFile f(old);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray(64 << 10, 'x'));
        }
        const QStringList pruned = flightlog::FlightLogWriter::pruneFolder(dir.path(), 0, dir.filePath(QStringLiteral("none.sortielog")));
        QCOMPARE(pruned, QStringList{QFileInfo(old).absoluteFilePath()});
        QVERIFY(QFile::exists(cleanLog) && QFile::exists(killedLog));

        // The operator's own client flies the vehicles.
        hci::HciSession session;
        hci::HciClient client(&session);
        client::ConnectionController connection(&session);
        client::VehicleFleet fleet(&client);
        QVERIFY(connection.connectToServer(sim.address(), QStringLiteral("admin"), QStringLiteral("admin")));
        QTRY_COMPARE_WITH_TIMEOUT(fleet.count(), 3, 10000);
        int rows[2] = {-1, -1};
        for (int row = 0; row < fleet.count(); ++row) {
            if (fleet.vehicleAt(row)->name() == QLatin1String("EMU-101"))
                rows[0] = row;
            if (fleet.vehicleAt(row)->name() == QLatin1String("EMU-102"))
                rows[1] = row;
        }
        QVERIFY(rows[0] >= 0 && rows[1] >= 0);
        Vehicle *emu101 = fleet.vehicleAt(rows[0]), *emu102 = fleet.vehicleAt(rows[1]);
        QTRY_VERIFY_WITH_TIMEOUT(emu101->position().isValid() && emu102->position().isValid(), 10000);
        const auto route101 = boxFrom(emu101->position()), route102 = boxFrom(emu102->position());
        for (const auto &[vehicle, route] : {std::pair{emu101, route101}, std::pair{emu102, route102}}) {
            Vehicle *v = vehicle; // a structured binding cannot be captured before C++20 in clang 14
            bool uploaded = false;
            QString why;
            // Through the link's two steps, as the upload service does: the server processes, then it is sent.
            v->link()->prepareMission(routeOf(route), [&, v](const vehicle::CommandResult &prepared, const vehicle::PreparedMission &mission) {
                if (!prepared.ok) {
                    why = prepared.message;
                    return;
                }
                v->link()->uploadMission(mission, {}, [&](const vehicle::CommandResult &r) {
                    uploaded = r.ok;
                    why = r.ok ? QStringLiteral("ok") : r.message;
                });
            });
            QTRY_VERIFY_WITH_TIMEOUT(!why.isEmpty(), 15000);
            QVERIFY2(uploaded, qPrintable(why));
            v->arm();
            QTRY_VERIFY_WITH_TIMEOUT(v->armed(), 10000);
            v->setMode(QStringLiteral("auto"));
        }
        // EMU-102 is sent 60 m west once it flies towards its third waypoint.
        QTRY_VERIFY_WITH_TIMEOUT(metresTo(emu102, route102[1]) < 2.5, 30000); // reached its second waypoint
        const mission::GeoPoint west = mission::geodesicDirect(route102[1], 270, 60).point;
        // Click-and-go, straight through the link (degrees, as VehicleLink takes them).
        emu102->link()->goTo(west.latitude, west.longitude, 12, 8, [](const vehicle::CommandResult &) {});

        // Mid-flight: SIGKILL one recorder.
        QTRY_VERIFY_WITH_TIMEOUT(metresTo(emu101, route101[1]) < 2.5, 30000);
        killed.kill();
        const qint64 killedAt = QDateTime::currentMSecsSinceEpoch();
        QVERIFY(killed.waitForFinished(5000));
        QCOMPARE(killed.exitStatus(), QProcess::CrashExit);

        QTRY_VERIFY_WITH_TIMEOUT(emu101->mode() == QLatin1String("hold") && metresTo(emu101, route101[3]) < 2.5, 30000);
        QTRY_VERIFY2_WITH_TIMEOUT(metresTo(emu102, west) < 5, qPrintable(QStringLiteral("%1 m, %2").arg(metresTo(emu102, west)).arg(emu102->mode())), 40000);
        clean.terminate(); // SIGTERM: the log is closed properly
        QTRY_VERIFY_WITH_TIMEOUT(clean.state() == QProcess::NotRunning, 15000);
        QCOMPARE(clean.exitStatus(), QProcess::NormalExit);
        QCOMPARE(clean.exitCode(), 0);
        QVERIFY(!QFile::exists(cleanLog + QStringLiteral("-wal")));

        // The killed recorder's log: whole up to at most the last second.
        {
            QString error;
            const auto log = FlightLog::open(killedLog, &error);
            QVERIFY2(log, qPrintable(error));
            QVERIFY2(log->stoppedAt().isEmpty(), qPrintable(log->stoppedAt()));
            QCOMPARE(log->vehicles().size(), size_t(3));
            const int v = log->vehicleIndex(QStringLiteral("EMU-101"));
            const auto lat = log->series(v, vehicle::TelemetryField::Latitude);
            QVERIFY(!lat.empty());
            qInfo("killed at %lld, last sample %lld: %lld ms lost", (long long)killedAt, (long long)lat.back().time, (long long)(killedAt - lat.back().time));
            QVERIFY2(killedAt - lat.back().time <= 1000, qPrintable(QString::number(killedAt - lat.back().time)));
        }

        // info
        Run info = sortieLog({QStringLiteral("info"), cleanLog, QStringLiteral("--json")});
        QCOMPARE(info.exitCode, 0);
        const QJsonObject infoJson = QJsonDocument::fromJson(info.out).object();
        QCOMPARE(infoJson.value(QStringLiteral("vehicles")).toArray().size(), 3);
        QStringList kinds;
        for (const QJsonValue &e : infoJson.value(QStringLiteral("events")).toArray())
            kinds << e.toObject().value(QStringLiteral("kind")).toString() + QLatin1Char(':') + e.toObject().value(QStringLiteral("vehicle")).toString();
        QVERIFY2(kinds.contains(QStringLiteral("armed:EMU-101")), qPrintable(kinds.join(QLatin1Char(' '))));
        QVERIFY2(kinds.contains(QStringLiteral("mode:EMU-102")), qPrintable(kinds.join(QLatin1Char(' '))));

        // export, each format parsed back
        for (const QString &format : {QStringLiteral("gpx"), QStringLiteral("kml"), QStringLiteral("csv")}) {
            const QString out = dir.filePath(QStringLiteral("tracks.") + format);
            Run e = sortieLog({QStringLiteral("export"), cleanLog, QStringLiteral("--format"), format, QStringLiteral("-o"), out});
            QVERIFY2(e.exitCode == 0, e.err.constData());
            QFile f(out);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QByteArray data = f.readAll();
            if (format == QLatin1String("csv")) {
                const QList<QByteArray> lines = data.split('\n');
                QVERIFY(lines.first().startsWith("time,vehicle,latitude [deg],longitude [deg],altitudeAmsl [m]"));
                QVERIFY(lines.size() > 100);
                continue;
            }
            QXmlStreamReader xml(data);
            int tracks = 0, points = 0;
            while (!xml.atEnd()) {
                if (xml.readNext() != QXmlStreamReader::StartElement)
                    continue;
                if (xml.name() == QLatin1String("trk") || xml.name() == QLatin1String("Track"))
                    ++tracks;
                if (xml.name() == QLatin1String("trkpt") || xml.name() == QLatin1String("coord"))
                    ++points;
            }
            QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
            QCOMPARE(tracks, 3);
            QVERIFY(points > 100);
        }
        Run one = sortieLog({QStringLiteral("export"), cleanLog, QStringLiteral("--format"), QStringLiteral("gpx"), QStringLiteral("--vehicle"), QStringLiteral("EMU-103")});
        QCOMPARE(one.exitCode, 0);
        QCOMPARE(one.out.count("<trk>"), 1);

        // compare: EMU-101 followed its plan; EMU-102 was sent elsewhere.
        const QString file101 = saveRoute(dir.filePath(QStringLiteral("emu101.sortie")), route101, QStringLiteral("Box 101"));
        const QString file102 = saveRoute(dir.filePath(QStringLiteral("emu102.sortie")), route102, QStringLiteral("Box 102"));
        Run c1 = sortieLog({QStringLiteral("compare"), cleanLog, file101, QStringLiteral("--vehicle"), QStringLiteral("EMU-101"), QStringLiteral("--json")});
        QVERIFY2(c1.exitCode == 0, c1.err.constData());
        const QJsonObject total1 = QJsonDocument::fromJson(c1.out).object().value(QStringLiteral("total")).toObject();
        QCOMPARE(total1.value(QStringLiteral("reached")).toInt(), 4);
        QCOMPARE(total1.value(QStringLiteral("missed")).toInt(), 0);
        // The copter cuts each corner inside its 2 m acceptance radius: at most 2·sin 45° = 1.4 m off a
        // right-angled turn (the approach to waypoint 1 from home is no leg: it counted 3.2 m on leg 1).
        // It climbs straight up before it moves, so leg 1 is flown at 12 m (its slant climb towards
        // waypoint 1 left it metres low where leg 1 begins, so only the mean was asserted).
        QVERIFY2(total1.value(QStringLiteral("maxCrossTrack")).toDouble() < 3.0, c1.out.constData());
        QVERIFY2(total1.value(QStringLiteral("maxAltitude")).toDouble() < 1.5, c1.out.constData());

        Run c2 = sortieLog({QStringLiteral("compare"), cleanLog, file102, QStringLiteral("--vehicle"), QStringLiteral("EMU-102"), QStringLiteral("--json")});
        QVERIFY2(c2.exitCode == 0, c2.err.constData());
        const QJsonObject result2 = QJsonDocument::fromJson(c2.out).object();
        const QJsonArray waypoints = result2.value(QStringLiteral("waypoints")).toArray();
        QCOMPARE(waypoints.size(), 4);
        QVERIFY(waypoints[0].toObject().value(QStringLiteral("reached")).toString() != QLatin1String("missed"));
        QVERIFY(waypoints[1].toObject().value(QStringLiteral("reached")).toString() != QLatin1String("missed"));
        QCOMPARE(waypoints[2].toObject().value(QStringLiteral("reached")).toString(), QStringLiteral("missed"));
        QCOMPARE(waypoints[3].toObject().value(QStringLiteral("reached")).toString(), QStringLiteral("missed"));
        const QJsonObject leg = result2.value(QStringLiteral("legs")).toArray()[1].toObject(); // 2nd to 3rd waypoint
        QVERIFY2(leg.value(QStringLiteral("maxCrossTrack")).toDouble() > 30, c2.out.constData());
        Run text = sortieLog({QStringLiteral("compare"), cleanLog, file102, QStringLiteral("--vehicle"), QStringLiteral("EMU-102")});
        QVERIFY(text.out.contains("2 reached, 2 missed"));

        // A route far from where the vehicle flew is refused.
        std::vector<mission::GeoPoint> far;
        for (const auto &p : route101)
            far.push_back({p.latitude + 0.2, p.longitude});
        Run refused = sortieLog({QStringLiteral("compare"), cleanLog, saveRoute(dir.filePath(QStringLiteral("far.sortie")), far, QStringLiteral("Far")),
                                 QStringLiteral("--vehicle"), QStringLiteral("EMU-101")});
        QCOMPARE(refused.exitCode, 1);
        QVERIFY2(refused.err.contains("does not match EMU-101"), refused.err.constData());
        Run unknown = sortieLog({QStringLiteral("compare"), cleanLog, file101, QStringLiteral("--vehicle"), QStringLiteral("EMU-999")});
        QCOMPARE(unknown.exitCode, 1);
        QVERIFY2(unknown.err.contains("EMU-999") && unknown.err.contains("EMU-101"), unknown.err.constData());
    }

    // The recorder takes commands from the fleet's command log: whatever sends them (the command bar's
    // policy, click-and-go on the map, which no vehicle signal reports), each is recorded with its result.
    void commandsSentThroughTheFleetAreRecorded()
    {
        Sim sim;
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("commands.sortielog"));
        hci::HciSession session;
        hci::HciClient client(&session);
        client::ConnectionController connection(&session);
        client::VehicleFleet fleet(&client);
        {
            flightlog::FlightRecorder recorder({path, {}, 100});
            QString error;
            QVERIFY2(recorder.start(&error), qPrintable(error));
            flightlog::FleetRecording recording(&fleet, &recorder, &session);
            QVERIFY(connection.connectToServer(sim.address(), QStringLiteral("admin"), QStringLiteral("admin")));
            QTRY_COMPARE_WITH_TIMEOUT(fleet.count(), 3, 10000);
            int row = -1;
            for (int r = 0; r < fleet.count(); ++r)
                if (fleet.vehicleAt(r)->name() == QLatin1String("EMU-101"))
                    row = r;
            QVERIFY(row >= 0);
            Vehicle *v = fleet.vehicleAt(row);
            QTRY_VERIFY_WITH_TIMEOUT(v->position().isValid(), 10000);
            const vehicle::CommandLog &log = *fleet.commandLog();
            QVERIFY(fleet.commands()->send(client::CommandPolicy::Command::Arm, v));
            fleet.goTo(row, v->position().latitude() + 0.0002, v->position().longitude());
            QTRY_VERIFY_WITH_TIMEOUT(log.count() == 2 && log.at(0).status != vehicle::CommandLog::Status::Pending
                                         && log.at(1).status != vehicle::CommandLog::Status::Pending, 15000);
            QCOMPARE(log.at(0).status, vehicle::CommandLog::Status::Done);
            // A closest-approach alert goes into the same log and is kept as an alert, not a command.
            const QString alert = QStringLiteral("EMU-101 and EMU-102: closest in 12 s, 5 m across and 2 m in height");
            fleet.commandLog()->alert(QStringLiteral("EMU-101"), alert);
            QTest::qWait(300); // the recorder flushes every 100 ms
            recorder.stop();

            QString openError;
            const auto recorded = FlightLog::open(path, &openError);
            QVERIFY2(recorded, qPrintable(openError));
            QStringList commands;
            for (const FlightLog::Event &e : recorded->events()) {
                if (e.kind == QLatin1String("command"))
                    commands << recorded->vehicles()[size_t(e.vehicle)].name() + QLatin1Char(':') + e.text + QStringLiteral(":%1").arg(e.ok);
            }
            const auto expected = [&](int i) {
                const vehicle::CommandLog::Entry &entry = log.at(i);
                return QStringLiteral("EMU-101:%1:%2").arg(entry.result.isEmpty() ? entry.command : entry.command + QStringLiteral(": ") + entry.result)
                    .arg(entry.status == vehicle::CommandLog::Status::Done ? 1 : 0);
            };
            QCOMPARE(commands, QStringList({expected(0), expected(1)}));
            QStringList alerts;
            for (const FlightLog::Event &e : recorded->events())
                if (e.kind == QLatin1String("alert"))
                    alerts << recorded->vehicles()[size_t(e.vehicle)].name() + QLatin1Char(':') + e.text;
            QCOMPARE(alerts, QStringList{QStringLiteral("EMU-101:") + alert});
            QVERIFY2(commands.at(1).startsWith(QLatin1String("EMU-101:go to ")), qPrintable(commands.join(QLatin1Char('\n'))));
        }
    }

    // The server's history of a vehicle, fetched in pages with progress, replays like a recording.
    void serverHistoryReplays()
    {
        Sim sim;
        hci::HciSession session;
        hci::HciClient client(&session);
        client::ConnectionController connection(&session);
        client::VehicleFleet fleet(&client);
        QVERIFY(connection.connectToServer(sim.address(), QStringLiteral("admin"), QStringLiteral("admin")));
        QTRY_COMPARE_WITH_TIMEOUT(fleet.count(), 3, 10000);
        Vehicle *v = nullptr;
        for (int row = 0; row < fleet.count(); ++row)
            if (fleet.vehicleAt(row)->name() == QLatin1String("EMU-103"))
                v = fleet.vehicleAt(row);
        QVERIFY(v);
        std::vector<vehicle::TelemetrySample> live;
        connect(v->link(), &vehicle::VehicleLink::telemetryReceived, this, [&](const vehicle::TelemetryBatch &batch) {
            for (const auto &u : batch)
                if (u.field == vehicle::TelemetryField::AltitudeAgl)
                    live.push_back({u.time, u.value});
        });
        QTRY_VERIFY_WITH_TIMEOUT(!live.empty(), 10000);
        v->arm();
        QTRY_VERIFY_WITH_TIMEOUT(v->armed(), 10000);
        v->takeoff(10);
        QTRY_VERIFY_WITH_TIMEOUT(v->altitudeAgl() > 4, 15000);
        const auto *link = qobject_cast<vehicle::HciVehicleLink *>(v->link());
        QVERIFY(link);
        com::ugcs::ucs::proto::Vehicle ref;
        ref.set_id(link->vehicleObjectId());
        ref.set_name("EMU-103");
        const std::vector<vehicle::TelemetrySample> seen = live;
        const qint64 from = seen.front().time, to = seen.back().time;

        flightlog::ServerHistory history(&client);
        QSignalSpy progress(&history, &flightlog::ServerHistory::progressChanged);
        QSignalSpy finished(&history, &flightlog::ServerHistory::finished);
        history.fetch(ref, from, to, 200);
        QVERIFY(history.isBusy());
        QVERIFY(finished.wait(15000));
        QVERIFY2(finished.first().first().toBool(), qPrintable(history.errorString()));
        QVERIFY2(history.pages() > 1, qPrintable(QString::number(history.pages())));
        QVERIFY(progress.count() >= history.pages());
        QCOMPARE(history.progress(), 1.0);

        flightlog::ReplayController replay;
        replay.open(history.takeLog());
        QCOMPARE(replay.fleet()->count(), 1);
        QCOMPARE(replay.fleet()->vehicleAt(0)->name(), QStringLiteral("EMU-103"));
        const auto fetched = replay.log()->series(0, vehicle::TelemetryField::AltitudeAgl);
        // Every value the live link received in the range is in the history, at its time.
        for (const auto &s : seen) {
            const auto it = std::find_if(fetched.begin(), fetched.end(), [&](const auto &f) { return f.time == s.time; });
            QVERIFY2(it != fetched.end(), qPrintable(QString::number(s.time)));
            QVERIFY(std::fabs(it->value - s.value) <= 0.0005);
        }
        replay.seek(to);
        QVERIFY(std::fabs(replay.fleet()->vehicleAt(0)->altitudeAgl() - seen.back().value) <= 0.0005);
    }

    void badUsage()
    {
        QCOMPARE(sortieLog({}).exitCode, 2);
        QCOMPARE(sortieLog({QStringLiteral("export"), QStringLiteral("x.sortielog"), QStringLiteral("--format"), QStringLiteral("shp")}).exitCode, 2);
        const Run missing = sortieLog({QStringLiteral("info"), QStringLiteral("/nonexistent/x.sortielog")});
        QCOMPARE(missing.exitCode, 1);
        QVERIFY(missing.err.contains("no such file"));
        // A login refused ends the recording with the reason.
        Sim sim;
        QProcess p;
        QByteArray err;
        connect(&p, &QProcess::readyReadStandardError, this, [&] { err += p.readAllStandardError(); });
        QTemporaryDir dir;
        p.start(QStringLiteral(SORTIE_LOG_PROGRAM), {QStringLiteral("record"), QStringLiteral("--server"), sim.address(), QStringLiteral("--user"),
                                                     QStringLiteral("admin"), dir.filePath(QStringLiteral("x.sortielog"))});
        QTRY_VERIFY_WITH_TIMEOUT(p.state() == QProcess::NotRunning, 15000);
        QCOMPARE(p.exitCode(), 1);
        QVERIFY2(!err.isEmpty(), "no reason given");
    }
};

QTEST_GUILESS_MAIN(TestSortieLog)
#include "tst_sortielog.moc"
