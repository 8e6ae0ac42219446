// A bad link between the operator and the simulated server, made by FaultProxy (and the server's own
// fault knobs): a link that goes silent, a slow server, answers out of order, garbage between frames
// and a frame header announcing 2 GiB. Each asserts what the operator sees and that nothing is lost.
#include "ResilienceSupport.h"
#include "RouteAnalyzer.h"

#include "FaultProxy.h"
#include "HciConnection.h"
#include "HciFrameCodec.h"
#include "HciMessageTypes.h"
#include "HciReply.h"
#include "Messages.pb.h"
#include "SimFixture.h"

#include <QGeoCoordinate>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

using namespace sortie;
using namespace std::chrono_literals;
using test::kDemoRoute;
using test::rowOf;
namespace pb = com::ugcs::ucs::proto;

namespace {

// Bytes that can never hold a plausible HCI header (no 0x48 0x50 "HP"), so a decoder that lost its
// place has to skip all of them.
QByteArray noise(qsizetype size, quint32 seed)
{
    QRandomGenerator random(seed);
    QByteArray bytes(size, Qt::Uninitialized);
    for (char &c : bytes) {
        c = char(random.bounded(256));
        if (c == 0x48)
            c = 0x47;
    }
    return bytes;
}

QByteArray header(int32_t instanceId, int32_t type, int32_t length, uint16_t signature = hci::kHciSignature)
{
    hci::HciFrameHeader h;
    h.signature = signature;
    h.instanceId = instanceId;
    h.type = type;
    h.length = length;
    QByteArray bytes(int(hci::kHciHeaderSize), Qt::Uninitialized);
    h.write(bytes.data());
    return bytes;
}

// The operator logged in through a proxy in front of an in-process simulated server, no vehicles
// (so the stream is quiet between requests), the demo route open.
struct Link
{
    Link()
        : proxy(QHostAddress::LocalHost, sim.server.port())
        , op(false)
    {
        proxy.listen();
        op.session.setRequestTimeout(2000ms);
    }

    bool openDemoRoute()
    {
        if (!op.logIn(QStringLiteral("127.0.0.1:%1").arg(proxy.port())))
            return false;
        QDeadlineTimer deadline(10000);
        while (rowOf(*op.missions.routes(), kDemoRoute) < 0 && !deadline.hasExpired())
            QTest::qWait(10);
        if (rowOf(*op.missions.routes(), kDemoRoute) < 0)
            return false;
        op.missions.openRoute(op.missions.routes()->objectIdAt(rowOf(*op.missions.routes(), kDemoRoute)));
        while (op.missions.document()->model()->count() != 4 && !deadline.hasExpired())
            QTest::qWait(10);
        return op.missions.document()->model()->count() == 4;
    }

    hci::HciConnection *connection() const { return op.session.connection(); }

    test::SimFixture sim;
    sim::FaultProxy proxy;
    test::Operator op;
};

} // namespace

class TestFaultyLink : public QObject
{
    Q_OBJECT

private slots:
    void silentLinkTimesOutThenRecovers()
    {
        Link link;
        QVERIFY(link.openDemoRoute());
        const int clientId = link.op.session.clientId();
        link.op.missions.document()->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820)); // typed before the link dies
        // The edit is analysed and the terrain under it fetched before the link dies, so the request
        // that times out below is the refresh, not the terrain's.
        QTRY_VERIFY_WITH_TIMEOUT(!link.op.missions.document()->analyzer()->isPending(), 10000);
        QTRY_COMPARE_WITH_TIMEOUT(link.connection()->pendingCount(), 0, 10000);

        link.proxy.setForwarding(false); // the connection stays open; nothing gets through
        link.op.missions.refresh();
        // The request times out with words the operator can read...
        QTRY_VERIFY_WITH_TIMEOUT(link.op.missions.message().contains(QStringLiteral("No answer to GetObjectListRequest within 2 s")), 10000);
        QVERIFY2(link.op.missions.message().startsWith(QStringLiteral("The server's routes could not be read")),
                 qPrintable(link.op.missions.message()));
        // ...and the session sees that the link is dead (not the server slow) and starts over.
        QTRY_COMPARE_WITH_TIMEOUT(link.op.connection.stateName(), QStringLiteral("Reconnecting"), 10000);
        QVERIFY2(link.op.session.lastError().message().contains(QStringLiteral("link seems dead")),
                 qPrintable(link.op.session.lastError().message()));
        QTRY_VERIFY(link.op.connection.detail().startsWith(QStringLiteral("connection lost; attempt")));
        // Saving now is refused in words, and the edit stays.
        link.op.missions.save();
        QVERIFY2(link.op.missions.message().startsWith(QStringLiteral("Not connected: your edits are kept")),
                 qPrintable(link.op.missions.message()));

        link.proxy.setForwarding(true);
        QTRY_COMPARE_WITH_TIMEOUT(link.op.connection.stateName(), QStringLiteral("Ready"), 15000);
        QCOMPARE(link.op.session.clientId(), clientId); // the same server session, re-attached
        QVERIFY(link.op.connection.errorString().isEmpty());
        QCOMPARE(link.op.missions.document()->model()->count(), 5);
        QSignalSpy saved(&link.op.missions, &client::MissionController::saved);
        link.op.missions.save();
        QVERIFY(saved.wait(10000));
        QCOMPARE(link.sim.world.store().find(QStringLiteral("Route"), link.op.missions.routeId())->route().segments_size(), 5);
    }

    void slowServerAnswersWithinTheTimeout()
    {
        Link link;
        QVERIFY(link.openDemoRoute());
        link.sim.server.faults().delayMs = 300; // the server is slow...
        link.proxy.setDelay(200);               // ...and so is the link: 0.5 s an answer, 2 s allowed
        QSignalSpy errors(&link.op.connection, &client::ConnectionController::errorChanged);
        const QStringList statesBefore = link.op.states;

        link.op.missions.document()->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820));
        QSignalSpy saved(&link.op.missions, &client::MissionController::saved);
        link.op.missions.save(); // lock, write, release: three slow round trips
        QVERIFY(saved.wait(15000));
        QVERIFY2(link.op.missions.message().startsWith(QStringLiteral("Saved")), qPrintable(link.op.missions.message()));
        link.op.missions.refresh(); // one more slow round trip: the server's route list
        QVERIFY(link.op.missions.isBusy());
        QTRY_VERIFY_WITH_TIMEOUT(!link.op.missions.isBusy(), 15000);
        QVERIFY2(link.op.missions.message().startsWith(QStringLiteral("Saved")), qPrintable(link.op.missions.message()));

        QCOMPARE(errors.count(), 0);
        QCOMPARE(link.op.states, statesBefore); // never left Ready
        QCOMPARE(link.connection()->framesDropped(), quint64(0)); // no answer came after its request gave up
    }

    void outOfOrderAnswersMatchTheirRequests()
    {
        Link link;
        QVERIFY(link.openDemoRoute());
        QTRY_COMPARE(link.op.missions.vehicles()->count(), 3);
        // Two lists of the same request type, answered newest first: routes must not show vehicles.
        link.sim.server.faults().reverseBatch = 2;
        link.op.missions.routes()->setEntries({});
        link.op.missions.vehicles()->setEntries({});
        link.op.missions.refresh();
        QTRY_VERIFY_WITH_TIMEOUT(link.op.missions.routes()->count() > 0 && link.op.missions.vehicles()->count() == 3, 10000);
        QVERIFY(rowOf(*link.op.missions.routes(), kDemoRoute) >= 0);
        QCOMPARE(rowOf(*link.op.missions.routes(), QStringLiteral("EMU-101")), -1);
        QCOMPARE(link.op.missions.vehicles()->nameAt(0), QStringLiteral("EMU-101"));

        // Four objects at once, answered in reverse: each reply carries the object it asked for.
        link.sim.server.faults().reverseBatch = 4;
        std::vector<std::pair<int, std::unique_ptr<hci::HciReply>>> replies;
        for (int row = 0; row < 3; ++row) {
            const int id = link.op.missions.vehicles()->objectIdAt(row);
            replies.emplace_back(id, link.op.client.getObject(hci::HciObjectType::Vehicle, id));
        }
        replies.emplace_back(link.op.missions.routeId(), link.op.client.getObject(hci::HciObjectType::Route, link.op.missions.routeId()));
        for (auto &[id, reply] : replies)
            reply->setAutoDelete(false);
        QTRY_VERIFY_WITH_TIMEOUT(std::all_of(replies.begin(), replies.end(), [](const auto &r) { return r.second->isFinished(); }), 10000);
        for (int i = 0; i < 4; ++i) {
            QVERIFY2(replies[i].second->isOk(), qPrintable(replies[i].second->error().message()));
            const pb::DomainObjectWrapper &object = replies[i].second->response<pb::GetObjectResponse>().object();
            QCOMPARE(i < 3 ? object.vehicle().id() : object.route().id(), replies[i].first);
        }
        QCOMPARE(link.connection()->framesDropped(), quint64(0));
    }

    void garbageBetweenFramesLosesNothing()
    {
        Link link;
        QVERIFY(link.openDemoRoute());
        const quint64 droppedBefore = link.connection()->framesDropped();
        const int answerType = *hci::HciMessageTypes::number(pb::GetObjectResponse::descriptor());
        // A junk frame with a bad signature, one whose payload is not protobuf, an answer nobody asked
        // for, and a header whose length cannot delimit anything followed by noise.
        QByteArray garbage = header(5, answerType, 40, 0x1234) + noise(40, 1);
        garbage += QByteArray::fromStdString(hci::encodeRawHciFrame(6, answerType, std::string(12, '\xff')));
        garbage += QByteArray::fromStdString(hci::encodeRawHciFrame(987654, answerType, std::string()));
        garbage += header(7, answerType, -5) + noise(4000, 2);
        // Garbage goes between frames: first the answers the client waits for (the terrain under the
        // opened route among them) are all in, so none is cut by it.
        QTRY_COMPARE_WITH_TIMEOUT(link.connection()->pendingCount(), 0, 10000);
        link.proxy.injectToClients(garbage);

        // The operator edits and saves: lock, write, release, list; every answer arrives behind garbage.
        link.op.missions.document()->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820));
        QSignalSpy saved(&link.op.missions, &client::MissionController::saved);
        link.op.missions.save();
        QTRY_VERIFY_WITH_TIMEOUT(link.connection()->framesDropped() >= droppedBefore + 4, 10000);
        QVERIFY(saved.wait(10000));
        QTRY_COMPARE_WITH_TIMEOUT(link.connection()->pendingCount(), 0, 10000);
        link.proxy.injectToClients(garbage);
        link.op.missions.refresh(); // the route list, read again behind the garbage
        QVERIFY(link.op.missions.isBusy());
        QTRY_VERIFY_WITH_TIMEOUT(!link.op.missions.isBusy(), 10000);
        QVERIFY2(!link.op.missions.message().startsWith(QStringLiteral("The server's routes could not be read")), qPrintable(link.op.missions.message()));

        QCOMPARE(link.connection()->framesDropped(), droppedBefore + 8); // each piece of garbage reported once
        QVERIFY(!link.op.states.contains(QStringLiteral("Reconnecting"))); // no reconnect was needed
        QVERIFY(link.op.connection.errorString().isEmpty());
        QCOMPARE(link.sim.world.store().find(QStringLiteral("Route"), link.op.missions.routeId())->route().segments_size(), 5);
    }

    void twoGiBLengthIsSurvivedWithBoundedMemory()
    {
        Link link;
        QVERIFY(link.openDemoRoute());
        hci::HciConnection *connection = link.connection();
        const quint64 droppedBefore = connection->framesDropped();
        const qint64 rssBefore = test::ProcessStats::of().residentKiB;
        const qint64 heapBefore = test::heapBytesInUse();

        // The event loop keeps turning while the flood is decoded: a heartbeat counts its turns.
        int beats = 0;
        QTimer heartbeat;
        QObject::connect(&heartbeat, &QTimer::timeout, [&beats] { ++beats; });
        heartbeat.start(5);

        // 0x80000000: 2 GiB unsigned, negative as the int32 the field is. Then 32 MiB of noise, fed no
        // faster than the client reads it so the proxy's own buffers stay small.
        link.proxy.injectToClients(header(9, 11, std::numeric_limits<int32_t>::min()));
        constexpr qsizetype kChunk = 256 * 1024;
        constexpr int kChunks = 128;
        const QByteArray chunk = noise(kChunk, 3);
        const int beatsAtStart = beats;
        quint64 expected = connection->bytesReceived() + hci::kHciHeaderSize;
        for (int i = 0; i < kChunks; ++i) {
            link.proxy.injectToClients(chunk);
            expected += quint64(kChunk);
            QVERIFY(test::waitUntil([&] { return connection->bytesReceived() >= expected; }));
        }
        const qint64 rssAfter = test::ProcessStats::of().residentKiB;
        const qint64 heapAfter = test::heapBytesInUse();
        QVERIFY2(beats > beatsAtStart, "the event loop did not turn while the garbage was decoded");

        // Later frames arrive: the operator's next request is answered.
        link.op.missions.document()->editor()->addWaypoint(QGeoCoordinate(56.9790, 24.0820));
        QSignalSpy saved(&link.op.missions, &client::MissionController::saved);
        link.op.missions.save();
        QVERIFY(saved.wait(10000));
        QCOMPARE(connection->framesDropped(), droppedBefore + 1); // the bad header, reported once
        QVERIFY(!link.op.states.contains(QStringLiteral("Reconnecting")));

        qInfo("2 GiB length + %lld MiB noise: VmRSS %lld KiB -> %lld KiB (+%lld KiB), %d heartbeats",
              qlonglong(kChunk * kChunks / (1024 * 1024)), qlonglong(rssBefore), qlonglong(rssAfter),
              qlonglong(rssAfter - rssBefore), beats - beatsAtStart);
        QVERIFY(rssBefore > 0);
        qInfo("heap in use %lld KiB -> %lld KiB (%+lld KiB)", qlonglong(heapBefore / 1024), qlonglong(heapAfter / 1024),
              qlonglong((heapAfter - heapBefore) / 1024));
        QVERIFY2(!test::kResidentMemoryIsMeaningful || rssAfter - rssBefore < 64 * 1024,
                 "memory grew by 64 MiB or more while garbage was decoded");
        // The allocator's count holds under ASan too: the 2 GiB length is never allocated.
        QVERIFY2(heapAfter - heapBefore < 64 * 1024 * 1024, "the heap grew by 64 MiB or more while garbage was decoded");
    }
};

QTEST_GUILESS_MAIN(TestFaultyLink)
#include "tst_faultylink.moc"
