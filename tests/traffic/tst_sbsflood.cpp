// An SBS-1 flood (issue 36): a receiver on 127.0.0.1 offering 200,000 MSG,3 lines, each a distinct
// ICAO address, to the feed and picture the client runs. The picture never holds more than its
// capacity, the ones it holds at the end are exactly the nearest to the view's centre, the feed
// takes every line (counted: messages, nothing dropped), and the views are told in gathered
// notifications, not one per report. No timing: how fast it goes is bench_sbsflood's.
#include "FloodFeeder.h"
#include "SbsFeed.h"
#include "TrafficPicture.h"

#include <QSignalSpy>
#include <QTest>

#include <algorithm>

using namespace sortie;
using namespace sortie::traffic;
using test::Flood;

class TestSbsFlood : public QObject
{
    Q_OBJECT

private slots:
    void aFloodOfAddressesKeepsTheNearestAndEveryLineIsTaken()
    {
        constexpr qint64 kLines = 200000;
        constexpr int kCapacity = 300;
        test::FloodFeeder feeder(Flood::lines(kLines));
        QVERIFY(feeder.port() > 0);

        TrafficPicture picture;
        picture.setCapacity(kCapacity);
        picture.setReference(Flood::kReferenceLatitude, Flood::kReferenceLongitude);
        int most = 0;
        connect(&picture, &QAbstractItemModel::rowsInserted, this, [&] { most = std::max(most, picture.count()); });
        QSignalSpy told(&picture, &QAbstractItemModel::dataChanged);
        QSignalSpy changed(&picture, &TrafficPicture::changed);
        SbsFeed feed(&picture);
        QVERIFY(feed.setAddress(QStringLiteral("127.0.0.1:%1").arg(feeder.port())));
        // Every line taken: the feed keeps up (a bound of minutes, never reached when it does).
        QTRY_COMPARE_WITH_TIMEOUT(feed.messages(), int(kLines), 300000);
        QCOMPARE(feed.droppedLines(), 0);
        picture.flush();

        QCOMPARE(picture.count(), kCapacity);
        QVERIFY(most <= kCapacity);
        QCOMPARE(picture.leftOut() + kCapacity <= kLines, true);
        // Exactly the nearest: ranks 0 .. capacity-1.
        std::vector<qint64> ranks;
        for (const TrafficAircraft &a : picture.aircraft()) {
            const qint64 i = qint64(a.state.address) - Flood::kFirstAddress;
            QVERIFY(i >= 0 && i < kLines);
            QCOMPARE(picture.find(a.state.address), &a);  // the index finds each one where it is
            ranks.push_back(Flood::rank(i, kLines));
            QVERIFY(std::abs(a.rangeM - Flood::distanceM(i, kLines)) < 1.0);
        }
        std::sort(ranks.begin(), ranks.end());
        for (int r = 0; r < kCapacity; ++r)
            QCOMPARE(ranks[size_t(r)], qint64(r));
        // Gathered: far fewer notifications than reports.
        QVERIFY2(told.count() * 100 < kLines, qPrintable(QString::number(told.count())));
        QVERIFY2(changed.count() * 100 < kLines, qPrintable(QString::number(changed.count())));
        feed.setAddress({});  // the feeder's thread ends when the client goes
    }

    void aSmallerCapacityDropsTheFarthest()
    {
        TrafficPicture picture;
        picture.setReference(Flood::kReferenceLatitude, Flood::kReferenceLongitude);
        for (quint32 i = 0; i < 10; ++i) {
            TrafficReport r;
            r.address = 0x400000 + i;
            r.latitude = Flood::kReferenceLatitude + (10 - i) * 0.01;  // the last reported is the nearest
            r.longitude = Flood::kReferenceLongitude;
            picture.report(r);
        }
        // One without a position yet: admitted while there is room, never over one with a position.
        TrafficReport unplaced;
        unplaced.address = 0x500000;
        picture.report(unplaced);
        QCOMPARE(picture.count(), 11);
        picture.setCapacity(4);
        QCOMPARE(picture.count(), 4);
        QVERIFY(!picture.find(0x500000));
        for (quint32 i = 6; i < 10; ++i)
            QVERIFY(picture.find(0x400000 + i));
        picture.report(unplaced);
        QVERIFY(!picture.find(0x500000));
        QCOMPARE(picture.leftOut(), qint64(1));
        // A newcomer nearer than the farthest takes its row.
        TrafficReport near;
        near.address = 0x600000;
        near.latitude = Flood::kReferenceLatitude;
        near.longitude = Flood::kReferenceLongitude;
        picture.report(near);
        QCOMPARE(picture.count(), 4);
        QVERIFY(picture.find(0x600000));
        QVERIFY(!picture.find(0x400006));  // the farthest of the four
        for (const TrafficAircraft &a : picture.aircraft())
            QCOMPARE(picture.find(a.state.address), &a);
    }
};

QTEST_GUILESS_MAIN(TestSbsFlood)
#include "tst_sbsflood.moc"
