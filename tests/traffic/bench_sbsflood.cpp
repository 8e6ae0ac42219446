// The SBS-1 flood of issue 36 through the whole path the client runs (socket, SbsFeed, SbsReader,
// TrafficPicture), and the picture's own update cost. A receiver thread on 127.0.0.1 offers 200,000
// MSG,3 lines of distinct addresses as fast as they are taken; printed: lines a second taken (wall
// and the GUI thread's CPU), the longest the event loop went without a turn (what a frame waits),
// and the picture's cost per report (newcomers refused or admitted; updates to held aircraft).
// Figures go in docs/performance.md, "Traffic".
#include "BenchClock.h"
#include "FloodFeeder.h"
#include "SbsFeed.h"
#include "TrafficPicture.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <cstdio>

using namespace sortie;
using namespace sortie::traffic;
using test::Flood;

namespace {

void wholePath(qint64 lines)
{
    test::FloodFeeder feeder(Flood::lines(lines));
    TrafficPicture picture;
    picture.setReference(Flood::kReferenceLatitude, Flood::kReferenceLongitude);
    SbsFeed feed(&picture);
    // A turn of the event loop every 0 ms when it is free: the longest gap is the longest stall.
    QTimer tick;
    tick.setInterval(0);
    QElapsedTimer sinceTick;
    double longestGapMs = 0;
    QObject::connect(&tick, &QTimer::timeout, [&] {
        if (feed.messages() > 0)
            longestGapMs = std::max(longestGapMs, double(sinceTick.nsecsElapsed()) / 1e6);
        sinceTick.restart();
    });
    QElapsedTimer wall;
    const double cpu0 = test::threadCpuMs();
    wall.start();
    sinceTick.start();
    tick.start();
    QEventLoop loop;
    QObject::connect(&feed, &SbsFeed::countsChanged, &loop, [&] {
        if (feed.messages() >= lines)
            loop.quit();
    });
    QTimer::singleShot(600000, &loop, &QEventLoop::quit);
    feed.setAddress(QStringLiteral("127.0.0.1:%1").arg(feeder.port()));
    loop.exec();
    const double wallS = double(wall.nsecsElapsed()) / 1e9, cpuS = (test::threadCpuMs() - cpu0) / 1e3;
    tick.stop();
    std::printf("bench_sbsflood: whole path: %d of %lld lines taken in %.2f s wall, %.2f s of the GUI thread's CPU: "
                "%.0f lines/s wall, %.0f lines/s of CPU; longest event-loop stall %.1f ms; picture holds %d (capacity %d), %lld left out; load %.2f\n",
                feed.messages(), (long long)lines, wallS, cpuS, feed.messages() / wallS, feed.messages() / cpuS, longestGapMs, picture.count(),
                picture.capacity(), (long long)picture.leftOut(), test::loadAverage());
    // Idle again once the flood stops: nothing left to do but the sweep.
    const double idle0 = test::threadCpuMs();
    QEventLoop idle;
    QTimer::singleShot(2000, &idle, &QEventLoop::quit);
    idle.exec();
    std::printf("bench_sbsflood: after the flood: %.1f ms of CPU in 2 s\n", test::threadCpuMs() - idle0);
    feed.setAddress({});
}

void pictureCost(qint64 lines)
{
    std::vector<TrafficReport> reports(static_cast<size_t>(lines));
    for (qint64 i = 0; i < lines; ++i) {
        TrafficReport &r = reports[size_t(i)];
        r.address = Flood::kFirstAddress + quint32(i);
        r.latitude = Flood::kReferenceLatitude + Flood::distanceM(i, lines) / 111195.0;
        r.longitude = Flood::kReferenceLongitude;
        r.altitudeM = 11000;
    }
    TrafficPicture picture;
    picture.setReference(Flood::kReferenceLatitude, Flood::kReferenceLongitude);
    double cpu0 = test::threadCpuMs();
    for (const TrafficReport &r : reports)
        picture.report(r);
    picture.flush();
    const double newcomersNs = (test::threadCpuMs() - cpu0) * 1e6 / double(lines);
    // Updates of the aircraft held: the steady state of a busy sky.
    std::vector<TrafficReport> held;
    for (const TrafficAircraft &a : picture.aircraft())
        held.push_back(a.state);
    constexpr int kRounds = 400;
    cpu0 = test::threadCpuMs();
    for (int round = 0; round < kRounds; ++round) {
        for (TrafficReport &r : held) {
            *r.latitude += 1e-6;
            picture.report(r);
        }
    }
    picture.flush();
    const double updateNs = (test::threadCpuMs() - cpu0) * 1e6 / double(held.size() * kRounds);
    std::printf("bench_sbsflood: picture (capacity %d): %.0f ns of CPU per newcomer report (%lld distinct, %lld left out), "
                "%.0f ns per update of a held aircraft (%zu x %d)\n",
                picture.capacity(), newcomersNs, (long long)lines, (long long)picture.leftOut(), updateNs, held.size(), kRounds);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    constexpr qint64 kLines = 200000;
    pictureCost(kLines);
    wholePath(kLines);
    return 0;
}
