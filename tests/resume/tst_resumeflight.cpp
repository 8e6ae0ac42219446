// A scan that needed two batteries, flown by sortie-sim's VCI vehicle over a real socket: sent home
// half-way, resumed from its last photo (core/resume), finished. The photos of both flights, as
// the client heard them on /camera/photo, cover the field with the planned overlap, none is taken
// twice at the same place, and each is in the flight log the client recorded.
#include "CommandCatcher.h"
#include "CoverageMap.h"
#include "ResumeRoute.h"
#include "ResumeTestRoute.h"

#include "FlightLog.h"
#include "FlightRecorder.h"
#include "Geodesy.h"
#include "PhotoEvents.h"
#include "Track.h"
#include "SimVciListener.h"
#include "SimVciVehicle.h"
#include "VciEndpoint.h"
#include "VciVehicleLink.h"
#include "Vehicle.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace sortie;

namespace {

using Outcome = test::CommandCatcher;

coverage::Shot shotOf(const vehicle::CameraPhoto &p)
{
    coverage::Shot s;
    s.name = QStringLiteral("photo %1").arg(p.sequence);
    s.latitude = p.latitude;
    s.longitude = p.longitude;
    s.heightAboveGround = p.altitudeAgl;
    s.headingDegrees = p.yaw;
    return s;
}

double nearest(const vehicle::CameraPhoto &p, const std::vector<vehicle::CameraPhoto> &others)
{
    double best = qInf();
    for (const vehicle::CameraPhoto &o : others)
        best = std::min(best, mission::geodesicDistance({p.latitude, p.longitude}, {o.latitude, o.longitude}));
    return best;
}

} // namespace

class TestResumeFlight : public QObject
{
    Q_OBJECT

    // Prepares the route for the vehicle, uploads it, arms and starts it.
    static void fly(vehicle::VciVehicleLink &link, const mission::Route &route)
    {
        bool prepared = false;
        vehicle::CommandResult prepareResult;
        vehicle::PreparedMission mission;
        link.prepareMission(route, [&](const vehicle::CommandResult &r, const vehicle::PreparedMission &m) {
            prepared = true;
            prepareResult = r;
            mission = m;
        });
        QTRY_VERIFY(prepared);
        QVERIFY2(prepareResult.ok, qPrintable(prepareResult.message));
        Outcome upload, arm, go;
        link.uploadMission(mission, {}, upload.callback());
        QTRY_VERIFY(upload.done);
        QVERIFY2(upload.result.ok, qPrintable(upload.result.message));
        link.arm(true, arm.callback());
        QTRY_VERIFY(arm.done);
        QVERIFY2(arm.result.ok, qPrintable(arm.result.message));
        link.setMode(vehicle::FlightMode::Auto, go.callback());
        QTRY_VERIFY(go.done);
        QVERIFY2(go.result.ok, qPrintable(go.result.message));
    }

private slots:
    void twoBatteriesOneSurvey()
    {
        sim::SimVciOptions options;
        options.homeLatitude = test::kResumeHome.latitude;
        options.homeLongitude = test::kResumeHome.longitude;
        options.timeScale = 20;
        sim::SimVciVehicle simVehicle(options);
        sim::SimVciListener listener(&simVehicle);
        QVERIFY(listener.listen(0));
        QString error;
        const auto endpoint = vci::VciEndpoint::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(listener.port()), &error);
        QVERIFY2(endpoint, qPrintable(error));
        vehicle::VciVehicleLink link(*endpoint);
        vehicle::Vehicle vehicle(&link);
        vehicle.setNotifyInterval(20);
        std::vector<vehicle::CameraPhoto> heard;
        connect(&vehicle, &vehicle::Vehicle::photoTaken, this, [&](const vehicle::CameraPhoto &p) { heard.push_back(p); });
        QTemporaryDir logs;
        QVERIFY(logs.isValid());
        const QString logPath = logs.filePath(QStringLiteral("survey.sortielog"));
        auto recorder = std::make_unique<flightlog::FlightRecorder>(flightlog::FlightRecorder::Options{logPath, {}, 100});
        QVERIFY2(recorder->start(&error), qPrintable(error));
        recorder->addVehicle(&vehicle);
        link.start();
        QTRY_VERIFY(vehicle.isConnected());
        QTRY_VERIFY(vehicle.position().isValid());

        // The first battery: about half the field, then home.
        const mission::Route route = test::resumeTestRoute();
        fly(link, route);
        QTRY_VERIFY_WITH_TIMEOUT(heard.size() >= 50, 60000);
        Outcome home;
        link.returnHome(home.callback());
        QTRY_VERIFY(home.done);
        QVERIFY2(home.result.ok, qPrintable(home.result.message));
        QTRY_VERIFY_WITH_TIMEOUT(!vehicle.armed(), 60000);
        const std::vector<vehicle::CameraPhoto> first = heard;
        QVERIFY2(first.size() < 60, qPrintable(QString::number(first.size())));  // none on the way home
        QTRY_COMPARE_WITH_TIMEOUT(heard.size(), simVehicle.shutter().photos().size(), 2000);
        QVERIFY(mission::geodesicDistance({vehicle.position().latitude(), vehicle.position().longitude()}, test::kResumeHome) < 3);

        // The battery changed: the rest, from the last photo.
        resume::ResumeRequest request;
        request.lastPhoto = {vehicle.lastPhoto().latitude, vehicle.lastPhoto().longitude};
        request.takeoff = {vehicle.position().latitude(), vehicle.position().longitude()};
        const auto plan = resume::resumeRoute(route, request);
        QVERIFY2(plan, qPrintable(plan ? QString() : plan.error().message));
        QCOMPARE(plan->resumedRow, 1);
        QVERIFY(plan->offPath < 5);
        fly(link, plan->route);
        QTRY_VERIFY_WITH_TIMEOUT(vehicle.missionState() == QLatin1String("complete"), 90000);
        QTRY_VERIFY_WITH_TIMEOUT(!vehicle.armed(), 60000);
        QTRY_COMPARE_WITH_TIMEOUT(heard.size(), simVehicle.shutter().photos().size(), 2000);
        const std::vector<vehicle::CameraPhoto> second(heard.begin() + qsizetype(first.size()), heard.end());
        QVERIFY2(second.size() > 20, qPrintable(QString::number(second.size())));

        // Heard in order, none missed.
        for (size_t i = 0; i < heard.size(); ++i)
            QCOMPARE(heard[i].sequence, qint64(i + 1));
        // None of the second flight where the first took one: the series took up one interval on.
        const auto &scan = std::get<mission::AreaScan>(route.segments[1]);
        const double along = 60.0 * scan.parameters.camera.sensorHeightMm / scan.parameters.camera.focalLengthMm;
        const double trigger = along * (1 - scan.parameters.frontOverlapPercent / 100);
        for (const vehicle::CameraPhoto &p : second)
            QVERIFY2(nearest(p, first) > trigger / 2, qPrintable(QStringLiteral("photo %1: %2 m from one of the first flight's")
                                                                   .arg(p.sequence).arg(nearest(p, first))));

        // Each is in the flight log, as it was heard: time, place, height and attitude.
        recorder.reset();
        const auto log = flightlog::FlightLog::open(logPath, &error);
        QVERIFY2(log, qPrintable(error));
        QCOMPARE(log->vehicles().size(), size_t(1));
        const std::vector<vehicle::CameraPhoto> logged = flightlog::photosOf(*log, 0);
        QCOMPARE(logged.size(), heard.size());
        for (size_t i = 0; i < logged.size(); ++i) {
            QCOMPARE(logged[i].sequence, heard[i].sequence);
            QCOMPARE(logged[i].time, heard[i].time);
            QCOMPARE(logged[i].latitude, heard[i].latitude);
            QCOMPARE(logged[i].altitudeAgl, heard[i].altitudeAgl);
            QCOMPARE(logged[i].yaw, heard[i].yaw);
            QCOMPARE(logged[i].gimbalTilt, 90.0);
        }
        // And geotagging reads them as the track's photos, to pair a card's photos with.
        const auto track = geotag::flightLogTrack(*log, 0, &error);
        QVERIFY2(track, qPrintable(error));
        QCOMPARE(track->photos.size(), heard.size());
        QCOMPARE(track->photos.back().sequence, heard.back().sequence);
        QCOMPARE(track->photos.back().time, heard.back().time);

        // Together they cover the field with the overlap planned; the first alone did not.
        std::vector<coverage::Shot> all, firstShots;
        for (const vehicle::CameraPhoto &p : heard)
            all.push_back(shotOf(p));
        for (const vehicle::CameraPhoto &p : first)
            firstShots.push_back(shotOf(p));
        coverage::CoverageOptions coverageOptions;
        coverageOptions.camera = scan.parameters.camera;
        coverageOptions.cellMeters = 1;
        const auto report = coverage::computeCoverage(all, coverageOptions, nullptr, &error);
        QVERIFY2(report, qPrintable(error));
        const auto half = coverage::computeCoverage(firstShots, coverageOptions, nullptr, &error);
        QVERIFY2(half, qPrintable(error));
        QCOMPARE(report->placed, int(heard.size()));
        QVERIFY2(report->holes.empty(),
                 qPrintable(QStringLiteral("%1 holes, the largest %2 m² %3 m from the resume point").arg(report->holes.size())
                                .arg(report->holes.empty() ? 0 : report->holes.front().areaSquareMeters)
                                .arg(report->holes.empty() ? 0 : mission::geodesicDistance({report->holes.front().centreLatitude, report->holes.front().centreLongitude}, plan->resumeAt))));
        QVERIFY2(report->coveredFraction > 0.99, qPrintable(QString::number(report->coveredFraction)));
        QVERIFY2(half->areaSquareMeters < 0.7 * report->areaSquareMeters,
                 qPrintable(QStringLiteral("%1 of %2 m²").arg(half->areaSquareMeters).arg(report->areaSquareMeters)));
        QVERIFY(report->forwardOverlap && report->sideOverlap);
        QVERIFY2(report->forwardOverlap->p50 > scan.parameters.frontOverlapPercent - 3, qPrintable(QString::number(report->forwardOverlap->p50)));
        QVERIFY2(report->forwardOverlap->p5 > scan.parameters.frontOverlapPercent - 10, qPrintable(QString::number(report->forwardOverlap->p5)));
        QVERIFY2(report->sideOverlap->p50 > scan.parameters.sideOverlapPercent - 3, qPrintable(QString::number(report->sideOverlap->p50)));
    }
};

QTEST_GUILESS_MAIN(TestResumeFlight)
#include "tst_resumeflight.moc"
