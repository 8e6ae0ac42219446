// The fit against sortie-sim's known battery model: two simulated VCI vehicles (over TCP, flying
// faster than real time on their own clocks) fly a mission with a hover, level cruise, a straight
// climb and descents while a FlightRecorder records each into its own .sortielog; the fit of those
// logs must give the sim's profile within 5 %. Then `sortie-log fit` runs as a process on them.
#include "CommandCatcher.h"
#include "EnergyProfile.h"
#include "FlightRecorder.h"
#include "FlightModel.h"
#include "LogFit.h"
#include "SimVciListener.h"
#include "SimVciVehicle.h"
#include "VciVehicleLink.h"
#include "Vehicle.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace sortie;
using namespace sortie::vehicle;

namespace {

// A vehicle of sortie-sim, the link to it and the recorder of its flight.
struct SimFlight
{
    std::unique_ptr<sim::SimVciVehicle> sim;
    std::unique_ptr<sim::SimVciListener> listener;
    std::unique_ptr<VciVehicleLink> link;
    std::unique_ptr<Vehicle> vehicle;
    std::unique_ptr<flightlog::FlightRecorder> recorder;
    QString log;
};

MissionItem at(double lat, double lon, double altitude, std::vector<MissionAction> actions = {})
{
    MissionItem item;
    item.latitude = lat;
    item.longitude = lon;
    item.altitude = altitude;
    item.actions = std::move(actions);
    return item;
}

MissionAction wait(double seconds)
{
    return {QStringLiteral("wait"), {{QStringLiteral("seconds"), seconds}}};
}

// Take-off and hover over home; cruise 700 m east; a straight climb of 60 m and a hover; cruise 700 m
// north; a straight descent of 70 m, a short hover, and the landing (descending) there.
std::vector<MissionItem> enduranceMission(double lat, double lon)
{
    double eastLat, eastLon, northLat, northLon;
    sim::sphericalDestination(lat, lon, 90, 700, &eastLat, &eastLon);
    sim::sphericalDestination(eastLat, eastLon, 0, 700, &northLat, &northLon);
    return {at(lat, lon, 30, {wait(40)}),
            at(eastLat, eastLon, 30),
            at(eastLat, eastLon, 90, {wait(20)}),
            at(northLat, northLon, 90),
            at(northLat, northLon, 20, {wait(10)}),
            at(northLat, northLon, 20, {{QStringLiteral("land"), {}}})};
}

double within(double fitted, double known)
{
    return std::abs(fitted - known) / known;
}

} // namespace

class TstSimFit : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_dir.setAutoRemove(qEnvironmentVariableIsEmpty("SORTIE_KEEP_LOGS")); // to look at the logs after a failure
        const endurance::EnergyProfile known = sim::simEnergyProfile();
        QVERIFY(known.problem().isEmpty());
        // Its speeds and rates are the sim's limits: what it flies is what the profile describes.
        const sim::FlightModel::Limits limits;
        QCOMPARE(limits.cruiseSpeed, known.cruiseSpeed);
        QCOMPARE(limits.climbRate, known.climbRate);
        QCOMPARE(limits.descentRate, known.descentRate);
    }

    void fitRecoversTheSimsProfile()
    {
        SimFlight a = fly(QStringLiteral("vci-a"), 56.9496, 24.1052);
        SimFlight b = fly(QStringLiteral("vci-b"), 56.9396, 24.1252);
        for (SimFlight *f : {&a, &b}) {
            Catch arm, go;
            f->link->arm(true, arm.callback());
            QTRY_VERIFY(arm.done);
            QVERIFY2(arm.result.ok, qPrintable(arm.result.message));
            f->link->setMode(FlightMode::Auto, go.callback());
            QTRY_VERIFY(go.done);
            QVERIFY2(go.result.ok, qPrintable(go.result.message));
        }
        // Flown until each has landed and disarmed itself: about 6 simulated minutes each. Not a
        // timed test: the bound only stops a vehicle that never lands.
        for (SimFlight *f : {&a, &b}) {
            QTRY_VERIFY_WITH_TIMEOUT(f->sim->model().state().missionComplete && !f->sim->model().state().armed, 180000);
            QTest::qWait(200); // the last battery reports on the ground
            f->recorder->stop();
        }
        m_logs = QStringList{a.log, b.log};

        const auto loaded = endurance::fit::loadFlights(m_logs);
        QVERIFY2(loaded.failures.isEmpty(), qPrintable(loaded.failures.join(u'\n')));
        QCOMPARE(loaded.traces.size(), size_t(2));
        QVERIFY(loaded.traces[0].currentReported);
        const endurance::fit::EnergyFit fit = endurance::fit::fitEnergy(loaded.traces);
        qInfo().noquote() << "\n" << endurance::fit::fitReport(fit);
        QString why;
        const auto profile = fit.profile(QStringLiteral("sim"), &why);
        QVERIFY2(profile, qPrintable(why));

        const endurance::EnergyProfile known = sim::simEnergyProfile();
        struct Check { const char *name; double fitted, known; };
        const Check checks[] = {{"hoverPowerW", profile->hoverPowerW, known.hoverPowerW},
                                {"cruisePowerW", profile->cruisePowerW, known.cruisePowerW},
                                {"cruiseSpeed", profile->cruiseSpeed, known.cruiseSpeed},
                                {"climbPowerW", profile->climbPowerW, known.climbPowerW},
                                {"climbRate", profile->climbRate, known.climbRate},
                                {"descentPowerW", profile->descentPowerW, known.descentPowerW},
                                {"descentRate", profile->descentRate, known.descentRate},
                                {"batteryWh", profile->batteryWh, known.batteryWh}};
        for (const Check &c : checks) {
            qInfo("%-14s fitted %8.2f  known %8.2f  (%+.2f %%)", c.name, c.fitted, c.known, 100.0 * (c.fitted - c.known) / c.known);
            QVERIFY2(within(c.fitted, c.known) < 0.05, c.name);
        }
        // Every phase had plenty of samples (several a simulated second), with a spread.
        for (const endurance::fit::Estimate *e : {&fit.hoverPowerW, &fit.cruisePowerW, &fit.climbPowerW, &fit.descentPowerW}) {
            QVERIFY(e->count >= 10);
            QVERIFY(std::isfinite(e->spread));
        }
        QCOMPARE(fit.batteryWh.count, 2);
    }

    // sortie-log fit on the same logs: the numbers, the profile written, a bad file named.
    void sortieLogFitEndToEnd()
    {
        QVERIFY2(m_logs.size() == 2, "needs the logs of fitRecoversTheSimsProfile");
        const QString out = m_dir.filePath(QStringLiteral("fitted.json"));
        QProcess p;
        p.start(QStringLiteral(SORTIE_LOG_PROGRAM), QStringList{QStringLiteral("fit")} + m_logs + QStringList{QStringLiteral("--out"), out});
        QVERIFY(p.waitForFinished(60000));
        const QString stdoutText = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(p.exitCode() == 0, qPrintable(QString::fromUtf8(p.readAllStandardError())));
        for (const char *line : {"hover power", "cruise power", "cruise speed", "climb power", "climb rate", "descent power",
                                 "descent rate", "battery"})
            QVERIFY2(stdoutText.contains(QLatin1String(line)), line);
        QVERIFY2(stdoutText.contains(QLatin1String("(n = ")) && stdoutText.contains(QStringLiteral("± ")), qPrintable(stdoutText));
        QVERIFY(!stdoutText.contains(QLatin1String("missing")));
        QFile file(out);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const auto profile = endurance::readEnergyProfile(file.readAll());
        QVERIFY2(profile.ok(), qPrintable(profile.ok() ? QString() : profile.error().toString()));
        QCOMPARE(profile->source, endurance::ProfileSource::Fit);
        QVERIFY(within(profile->hoverPowerW, sim::simEnergyProfile().hoverPowerW) < 0.05);

        // A file that is no log is named with the reason; the others are still fitted; exit 1.
        const QString bad = m_dir.filePath(QStringLiteral("bad.sortielog"));
        QFile junk(bad);
        QVERIFY(junk.open(QIODevice::WriteOnly));
        junk.write("not a flight log");
        junk.close();
        p.start(QStringLiteral(SORTIE_LOG_PROGRAM), QStringList{QStringLiteral("fit"), m_logs.first(), bad});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 1);
        QVERIFY(QString::fromUtf8(p.readAllStandardError()).contains(QLatin1String("bad.sortielog")));
        QVERIFY(QString::fromUtf8(p.readAllStandardOutput()).contains(QLatin1String("hover power")));

        // No log at all: bad usage.
        p.start(QStringLiteral(SORTIE_LOG_PROGRAM), QStringList{QStringLiteral("fit")});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 2);
    }

private:
    using Catch = test::CommandCatcher;

    // A sim vehicle on its own clock at 20×, its link, its mission up and its recorder running.
    SimFlight fly(const QString &id, double lat, double lon)
    {
        SimFlight f;
        sim::SimVciOptions options;
        options.id = id;
        options.name = id.toUpper();
        options.homeLatitude = lat;
        options.homeLongitude = lon;
        options.timeScale = 20;
        options.simulatedClock = true;
        options.telemetryRate = 50; // a report a tick: every 0.4 simulated seconds
        f.sim = std::make_unique<sim::SimVciVehicle>(options);
        f.listener = std::make_unique<sim::SimVciListener>(f.sim.get());
        if (!f.listener->listen(0))
            qFatal("no port for the simulated vehicle");
        QString error;
        const auto endpoint = vci::VciEndpoint::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(f.listener->port()), &error);
        if (!endpoint)
            qFatal("%s", qPrintable(error));
        f.link = std::make_unique<VciVehicleLink>(*endpoint, nullptr);
        f.vehicle = std::make_unique<Vehicle>(f.link.get());
        f.log = m_dir.filePath(id + QStringLiteral(".sortielog"));
        f.recorder = std::make_unique<flightlog::FlightRecorder>(flightlog::FlightRecorder::Options{f.log, {}, 500});
        if (!f.recorder->start(&error))
            qFatal("%s", qPrintable(error));
        f.recorder->addVehicle(f.vehicle.get());
        f.link->start();
        if (!QTest::qWaitFor([&] { return f.vehicle->isConnected(); }, 10000))
            qFatal("the simulated vehicle did not connect");
        PreparedMission mission;
        mission.items = enduranceMission(lat, lon);
        Catch upload;
        f.link->uploadMission(mission, {}, upload.callback());
        if (!QTest::qWaitFor([&] { return upload.done; }, 10000) || !upload.result.ok)
            qFatal("upload failed: %s", qPrintable(upload.result.message));
        return f;
    }

    QTemporaryDir m_dir;
    QStringList m_logs;
};

QTEST_GUILESS_MAIN(TstSimFit)
#include "tst_simfit.moc"
