// The traffic picture: partial reports merged by address, units converted, velocity east-north-up,
// stale after 60 s and removed after 120 s on an injected clock, absent values absent.
#include "HciTrafficSource.h"
#include "Messages.pb.h"
#include "SbsReader.h"
#include "TrafficPicture.h"

#include <QSignalSpy>
#include <QTest>

#include <limits>
#include <numbers>

using namespace sortie::traffic;
namespace pb = com::ugcs::ucs::proto;

namespace {

const std::string kTime = "2026/11/26,18:44:00.123,2026/11/26,18:44:00.125";

// Reads hand-written SBS lines into the picture, as the feed does.
void feed(TrafficPicture &picture, const std::vector<std::string> &lines)
{
    sbs::SbsReader reader;
    for (const std::string &line : lines)
        reader.push(line + "\r\n");
    while (auto r = reader.next()) {
        if (const auto *error = std::get_if<sbs::SbsError>(&*r))
            QFAIL(error->reason.c_str()); // a line of this test is wrong
        picture.report(reportFromSbs(std::get<sbs::SbsMessage>(*r)));
    }
}

} // namespace

class TestTrafficPicture : public QObject
{
    Q_OBJECT

    qint64 m_now = 1000000;
    TrafficPicture::Clock clock()
    {
        return [this] { return m_now; };
    }

private slots:
    void init() { m_now = 1000000; }

    void partialMessagesMerge()
    {
        TrafficPicture picture(clock());
        feed(picture, {"MSG,1,1,1,4CA2D6,1," + kTime + ",RYR2PN,,,,,,,,,,,",
                       "MSG,3,1,1,4CA2D6,1," + kTime + ",,37000,,,56.97650,24.07600,,,0,0,0,0",
                       "MSG,4,1,1,4CA2D6,1," + kTime + ",,,452,90,,,-640,,,,,",
                       "MSG,3,1,1,502C11,1," + kTime + ",,820,,,56.9,24.1,,,0,0,0,0"});
        QCOMPARE(picture.count(), 2);
        const TrafficAircraft *a = picture.find(0x4CA2D6);
        QVERIFY(a);
        QCOMPARE(a->state.callsign.value(), QStringLiteral("RYR2PN"));
        QCOMPARE(a->state.latitude.value(), 56.9765);
        QCOMPARE(a->state.altitudeM.value(), 37000 * 0.3048);
        QCOMPARE(a->state.altitudeReference, AltitudeReference::Barometric);
        QCOMPARE(a->state.groundSpeedMps.value(), 452 * 1852.0 / 3600.0);
        QCOMPARE(a->state.verticalRateMps.value(), -640 * 0.3048 / 60.0);
        // Due east: all of the speed east, none north; the vertical rate is up.
        const auto v = velocityOf(a->state);
        QVERIFY(v);
        QVERIFY(qAbs(v->east - 452 * 1852.0 / 3600.0) < 1e-9);
        QVERIFY(qAbs(v->north) < 1e-9);
        QCOMPARE(v->up.value(), -640 * 0.3048 / 60.0);

        // The model: roles by name; what no message said is an invalid QVariant, not 0.
        const QModelIndex first = picture.index(0);
        QCOMPARE(picture.data(first, TrafficPicture::AddressRole).toString(), QStringLiteral("4CA2D6"));
        QCOMPARE(picture.data(first, TrafficPicture::AltitudeReferenceRole).toString(), QStringLiteral("barometric"));
        QCOMPARE(picture.data(first, TrafficPicture::SourceRole).toString(), QStringLiteral("receiver"));
        QVERIFY(!picture.data(first, TrafficPicture::SquawkRole).isValid());
        const QModelIndex second = picture.index(1);
        QVERIFY(!picture.data(second, TrafficPicture::CallsignRole).isValid());
        QVERIFY(!picture.data(second, TrafficPicture::GroundSpeedRole).isValid());
        QVERIFY(!picture.data(second, TrafficPicture::VelocityEastRole).isValid()); // no track, no velocity
        QCOMPARE(picture.data(second, Qt::DisplayRole).toString(), QStringLiteral("502C11")); // no call sign: the address
    }

    // A later message changes only what it carries.
    void laterReportsKeepWhatTheyDoNotCarry()
    {
        TrafficPicture picture(clock());
        feed(picture, {"MSG,3,1,1,4CA2D6,1," + kTime + ",,37000,,,56.9,24.0,,,0,0,0,0", "MSG,5,1,1,4CA2D6,1," + kTime + ",,36000,,,,,,,0,,0,0"});
        const TrafficAircraft *a = picture.find(0x4CA2D6);
        QCOMPARE(a->state.altitudeM.value(), 36000 * 0.3048);
        QCOMPARE(a->state.latitude.value(), 56.9);
    }

    // Both sources about one aircraft: the server's MSL altitude is kept over the receiver's
    // pressure altitude, until the server has said nothing for 10 s.
    void mslAltitudeIsPreferred()
    {
        TrafficPicture picture(clock());
        TrafficReport server;
        server.address = 0x502C11;
        server.source = TrafficSource::Server;
        server.altitudeM = 250;
        server.altitudeReference = AltitudeReference::MeanSeaLevel;
        picture.report(server);
        feed(picture, {"MSG,5,1,1,502C11,1," + kTime + ",,800,,,,,,,0,,0,0"});
        QCOMPARE(picture.aircraft()[0].state.altitudeM.value(), 250.0);
        QCOMPARE(picture.aircraft()[0].state.altitudeReference, AltitudeReference::MeanSeaLevel);
        m_now += TrafficPicture::kMslAltitudePreferredMs;
        feed(picture, {"MSG,5,1,1,502C11,1," + kTime + ",,800,,,,,,,0,,0,0"});
        QCOMPARE(picture.aircraft()[0].state.altitudeM.value(), 800 * 0.3048);
        QCOMPARE(picture.aircraft()[0].state.altitudeReference, AltitudeReference::Barometric);
        picture.report(server);
        QCOMPARE(picture.aircraft()[0].state.altitudeReference, AltitudeReference::MeanSeaLevel);
    }

    void staleAfterAMinuteGoneAfterTwo()
    {
        TrafficPicture picture(clock());
        QSignalSpy changed(&picture, &TrafficPicture::changed);
        feed(picture, {"MSG,3,1,1,4CA2D6,1," + kTime + ",,37000,,,56.9,24.0,,,0,0,0,0"});
        m_now += TrafficPicture::kStaleAfterMs - 1;
        picture.sweep();
        QVERIFY(!picture.aircraft()[0].stale);
        m_now += 1;
        picture.sweep();
        QVERIFY(picture.aircraft()[0].stale);
        QVERIFY(picture.data(picture.index(0), TrafficPicture::StaleRole).toBool());
        // Heard again: fresh.
        feed(picture, {"MSG,8,1,1,4CA2D6,1," + kTime + ",,,,,,,,,,,,0"});
        QVERIFY(!picture.aircraft()[0].stale);
        m_now += TrafficPicture::kRemoveAfterMs - 1;
        picture.sweep();
        QCOMPARE(picture.count(), 1);
        QVERIFY(picture.aircraft()[0].stale);
        m_now += 1;
        picture.sweep();
        QCOMPARE(picture.count(), 0);
        QVERIFY(changed.count() >= 4);
    }

    // The server repeating an entry with the same updateTime does not keep it alive.
    void serverRepeatsDoNotRefresh()
    {
        TrafficPicture picture(clock());
        pb::AdsbAircraft a;
        a.set_icaoaddress(0x502C22);
        a.set_updatetime(5000);
        a.set_identification("BTI7TR");
        a.set_latitude(56.97 * std::numbers::pi / 180);
        a.set_longitude(24.07 * std::numbers::pi / 180);
        a.set_mslaltitude(700);
        a.set_heading(std::numbers::pi / 2);
        a.set_groundspeed(60);
        a.set_verticalvelocity(std::numeric_limits<double>::quiet_NaN()); // not believed
        const auto report = HciTrafficSource::reportFromAdsb(a);
        QVERIFY(report);
        QCOMPARE(report->latitude.value(), 56.97);
        QCOMPARE(report->trackDeg.value(), 90.0);
        QCOMPARE(report->altitudeReference, AltitudeReference::MeanSeaLevel);
        QVERIFY(!report->verticalRateMps);
        picture.report(*report);
        m_now += 30000;
        picture.report(*report); // the same updateTime
        QCOMPARE(picture.aircraft()[0].lastSeenMs, qint64(1000000));
        a.set_updatetime(35000);
        picture.report(*HciTrafficSource::reportFromAdsb(a));
        QCOMPARE(picture.aircraft()[0].lastSeenMs, qint64(1030000));
        QCOMPARE(picture.data(picture.index(0), TrafficPicture::SourceRole).toString(), QStringLiteral("server"));
        pb::AdsbAircraft anonymous; // no address: nothing to file it under
        QVERIFY(!HciTrafficSource::reportFromAdsb(anonymous));
    }
};

QTEST_MAIN(TestTrafficPicture)
#include "tst_trafficpicture.moc"
