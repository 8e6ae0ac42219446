// The simulated camera's shutter (sim/flight/SimShutter.h) on the flight model it rides: series by
// distance and time as a mission's camera actions start them, and no pictures once it leaves the
// mission.
#include "FlightModel.h"
#include "SimShutter.h"

#include <QtTest>

using sortie::sim::FlightModel;
using sortie::sim::SimPhoto;
using sortie::sim::SimShutter;

namespace {

constexpr double kLat = 56.95, kLon = 24.10;

// A model flying a straight 400 m leg east at 8 m/s, 50 m up, with the shutter run by its actions.
struct Flight
{
    FlightModel model{kLat, kLon, 10};
    SimShutter shutter;
    double seconds = 0;
    std::function<void(int)> atWaypoint;

    Flight()
    {
        double lat = 0, lon = 0, lat2 = 0, lon2 = 0;
        sortie::sim::sphericalDestination(kLat, kLon, 90, 50, &lat, &lon);
        sortie::sim::sphericalDestination(kLat, kLon, 90, 450, &lat2, &lon2);
        FlightModel::Waypoint start{lat, lon, 50, 8};
        FlightModel::Waypoint end{lat2, lon2, 50, 8};
        model.setMission({start, end});
        model.setWaypointReached([this](int i) {
            if (atWaypoint)
                atWaypoint(i);
        });
        model.arm();
        model.startMission();
    }
    SimShutter::Clock clock() const { return {seconds, int64_t(1'765'000'000'000) + int64_t(seconds * 1000)}; }
    void run(double forSeconds, double dt = 0.05)
    {
        for (double t = 0; t < forSeconds; t += dt) {
            seconds += dt;
            model.tick(dt);
            shutter.tick(model.state(), clock());
        }
    }
    bool runUntil(const std::function<bool()> &done, double limit = 600)
    {
        for (double t = 0; t < limit && !done(); t += 0.05)
            run(0.05);
        return done();
    }
};

double metresBetween(const SimPhoto &a, const SimPhoto &b)
{
    return sortie::sim::sphericalDistance(a.latitude, a.longitude, b.latitude, b.longitude);
}

} // namespace

class TestSimShutter : public QObject
{
    Q_OBJECT

private slots:
    // Started at the first waypoint, stopped at the second: a photo there, then one every 25 m.
    void takesASeriesByDistance()
    {
        Flight f;
        f.atWaypoint = [&f](int i) {
            if (i == 0)
                f.shutter.startByDistance(25, 0, 0, f.clock());
            else
                f.shutter.startByDistance(0, 0, 0, f.clock());  // 0 stops it
        };
        QVERIFY(f.runUntil([&] { return f.model.state().missionComplete; }));
        f.run(5);
        const auto &photos = f.shutter.photos();
        // 400 m at 25 m: the one at the start, 16 after (the last at the end, within a tick's flight).
        QVERIFY2(photos.size() == 16 || photos.size() == 17, qPrintable(QString::number(photos.size())));
        QVERIFY(!f.shutter.seriesRunning());
        for (size_t i = 1; i < photos.size(); ++i) {
            QCOMPARE(photos[i].sequence, int(i) + 1);
            const double d = metresBetween(photos[i - 1], photos[i]);
            QVERIFY2(std::abs(d - 25) < 0.5, qPrintable(QStringLiteral("%1: %2 m").arg(i).arg(d)));
            QVERIFY(photos[i].time > photos[i - 1].time);
        }
        // Spacing on average the interval: the tick's overshoot is carried over.
        QVERIFY(std::abs(metresBetween(photos.front(), photos[15]) - 15 * 25) < 0.5);
        QVERIFY(std::abs(photos[3].altitudeAgl - 50) < 0.5);
        QVERIFY(std::abs(photos[3].heading - 90) < 1);
        QCOMPARE(photos[3].gimbalTilt, 90.0);
    }

    // Every 2 s for 5 shots, after a 1 s delay; the gimbal's tilt is stamped on each.
    void takesASeriesByTimeWithItsShotsAndDelay()
    {
        Flight f;
        f.atWaypoint = [&f](int i) {
            if (i == 0) {
                f.shutter.setGimbalTilt(60);
                f.shutter.startByTime(2, 5, 1, f.clock());
            }
        };
        QVERIFY(f.runUntil([&] { return f.model.state().currentWaypoint == 1; }));
        const double startedAt = f.seconds;
        f.run(20);
        const auto &photos = f.shutter.photos();
        QCOMPARE(photos.size(), size_t(5));
        QVERIFY(!f.shutter.seriesRunning());
        QVERIFY2(std::abs(double(photos.front().time) / 1000 - (1'765'000'000 + startedAt + 1)) < 0.1, "the first after the delay");
        for (size_t i = 1; i < photos.size(); ++i)
            QVERIFY(std::abs(double(photos[i].time - photos[i - 1].time) - 2000) < 60);
        QCOMPARE(photos.back().gimbalTilt, 60.0);
    }

    // Sent home half-way, the series ends: no pictures on the way back. A hold pauses it.
    void stopsWhenTheVehicleLeavesTheMission()
    {
        Flight f;
        f.atWaypoint = [&f](int i) {
            if (i == 0)
                f.shutter.startByDistance(20, 0, 0, f.clock());
        };
        QVERIFY(f.runUntil([&] { return f.shutter.photos().size() == 5; }));
        QVERIFY(f.model.pause().empty());
        f.run(10);
        QCOMPARE(f.shutter.photos().size(), size_t(5));
        QVERIFY(f.shutter.seriesRunning());
        QVERIFY(f.model.resume().empty());
        QVERIFY(f.runUntil([&] { return f.shutter.photos().size() == 7; }));
        QVERIFY(std::abs(metresBetween(f.shutter.photos()[5], f.shutter.photos()[6]) - 20) < 0.5);
        QVERIFY(f.model.returnHome().empty());
        f.run(60);
        QVERIFY(!f.shutter.seriesRunning());
        QCOMPARE(f.shutter.photos().size(), size_t(7));
    }

    void takesASingleShot()
    {
        Flight f;
        f.run(1);
        f.shutter.single(f.model.state(), f.clock());
        QCOMPARE(f.shutter.photos().size(), size_t(1));
        QCOMPARE(f.shutter.photos().front().latitude, f.model.state().latitude);
        f.run(5);
        QCOMPARE(f.shutter.photos().size(), size_t(1));
    }
};

QTEST_GUILESS_MAIN(TestSimShutter)
#include "tst_simshutter.moc"
