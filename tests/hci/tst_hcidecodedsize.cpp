// HCI frames that would decode into far more memory than they occupy (issue 36): protobuf lets two
// bytes on the wire (an empty sub-message) become an object of hundreds of bytes, so 1 MiB of empty
// DomainObjectWrappers is over 256 MiB once parsed. The decoder estimates what a big payload would
// allocate without allocating it and drops it past kHciMaxDecodedBytes, naming why; real frames of
// the same size decode as before; the estimate follows what protobuf really allocates.
#include "HciConnection.h"
#include "HciDecodedSize.h"
#include "HciFrameCodec.h"
#include "HciMessageTypes.h"
#include "HciReply.h"
#include "Messages.pb.h"
#include "ProcessStats.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QtTest>

using namespace sortie;
using namespace sortie::hci;
namespace pb = com::ugcs::ucs::proto;

namespace {

// `count` empty DomainObjectWrappers (field 2 of GetObjectListResponse): two bytes each.
std::string emptyWrappers(size_t count)
{
    pb::GetObjectListResponse head;
    head.set_objecttype("Vehicle");
    std::string wire = head.SerializeAsString();
    wire.reserve(wire.size() + 2 * count);
    for (size_t i = 0; i < count; ++i)
        wire.append("\x12\x00", 2);
    return wire;
}

// A real list of the same order of size: vehicles with names, serials and telemetry-free fields.
pb::GetObjectListResponse vehicles(int count)
{
    pb::GetObjectListResponse list;
    list.set_objecttype("Vehicle");
    for (int i = 0; i < count; ++i) {
        pb::Vehicle *v = list.add_objects()->mutable_vehicle();
        v->set_id(i + 1);
        v->set_name("Survey hexacopter " + std::to_string(i + 1) + " of the northern block, spare batteries in case B");
        v->set_tag("SN-" + std::to_string(100000 + i));
        v->set_tailnumber("YL-" + std::to_string(i));
    }
    return list;
}

int32_t typeOf(const google::protobuf::Message &m)
{
    return *HciMessageTypes::number(m.GetDescriptor());
}

} // namespace

class TestHciDecodedSize : public QObject
{
    Q_OBJECT

private slots:
    void theEstimateFollowsWhatProtobufAllocates_data()
    {
        QTest::addColumn<bool>("hostile");
        QTest::newRow("empty wrappers") << true;
        QTest::newRow("real vehicles") << false;
    }

    void theEstimateFollowsWhatProtobufAllocates()
    {
        QFETCH(bool, hostile);
        const std::string wire = hostile ? emptyWrappers(20000) : vehicles(2000).SerializeAsString();
        pb::GetObjectListResponse parsed;
        QVERIFY(parsed.ParseFromString(wire));
        const auto estimate = estimateDecodedBytes(wire, *pb::GetObjectListResponse::descriptor(), SIZE_MAX);
        QVERIFY(estimate);
        const double actual = double(parsed.SpaceUsedLong());
        qInfo("%zu wire bytes: estimated %zu, protobuf's own count %.0f", wire.size(), *estimate, actual);
        // Close enough to bound by: never far under (an attacker's margin), never far over (a false alarm).
        QVERIFY2(double(*estimate) > 0.8 * actual && double(*estimate) < 2.0 * actual, qPrintable(QString::number(*estimate)));
        if (hostile)
            QVERIFY(actual > 100.0 * double(wire.size())); // the expansion this guards against
    }

    void theWalkStopsOnceOverTheLimit()
    {
        const std::string wire = emptyWrappers(100000);
        const auto estimate = estimateDecodedBytes(wire, *pb::GetObjectListResponse::descriptor(), 1 << 20);
        QVERIFY(estimate);
        QVERIFY(*estimate > size_t(1 << 20));
        QVERIFY(*estimate < size_t(2 << 20)); // stopped near the limit, not at the end
    }

    void malformedBytesAreLeftToTheParser_data()
    {
        QTest::addColumn<QByteArray>("wire");
        QTest::newRow("length past the end") << QByteArray("\x12\x7f\x00", 3);
        QTest::newRow("truncated varint") << QByteArray("\x08\xff\xff", 3);
        QTest::newRow("field number 0") << QByteArray("\x00\x01", 2);
        QTest::newRow("end group outside a group") << QByteArray("\x0c", 1);
        QTest::newRow("group without its end") << QByteArray("\x1b\x08\x01", 3);
        QTest::newRow("wire type 7") << QByteArray("\x0f", 1);
        QByteArray deep;
        for (int i = 0; i < 120; ++i) // DomainObjectWrapper -> ... nested past protobuf's limit of 100
            deep.prepend(QByteArray("\x0a") + char(deep.size()));
        QTest::newRow("nested past 100") << deep;
    }

    void malformedBytesAreLeftToTheParser()
    {
        QFETCH(QByteArray, wire);
        QVERIFY(!estimateDecodedBytes(std::string_view(wire.constData(), size_t(wire.size())),
                                      *pb::GetObjectListResponse::descriptor()));
    }

    void theDecoderDropsAFrameThatWouldExpandAndGoesOn()
    {
        const std::string bomb = emptyWrappers(kHciPrescanFromBytes); // 2 MiB on the wire
        HciFrameDecoder decoder;
        decoder.feed(encodeRawHciFrame(7, typeOf(pb::GetObjectListResponse()), bomb));
        decoder.feed(*encodeHciFrame(8, vehicles(3)));
        auto first = decoder.next();
        QVERIFY(first);
        const auto *dropped = std::get_if<HciDroppedFrame>(&*first);
        QVERIFY(dropped);
        QCOMPARE(dropped->reason, HciDropReason::TooLarge);
        QCOMPARE(dropped->header.instanceId, 7);
        QVERIFY2(dropped->detail.find("GetObjectListResponse of 2097") != std::string::npos, dropped->detail.c_str());
        auto second = decoder.next();
        QVERIFY(second);
        const auto *frame = std::get_if<HciFrame>(&*second);
        QVERIFY(frame);
        QCOMPARE(static_cast<const pb::GetObjectListResponse &>(*frame->message).objects_size(), 3);
    }

    void aRealListOfTheSameSizeStillDecodes()
    {
        const pb::GetObjectListResponse list = vehicles(30000);
        QVERIFY(list.ByteSizeLong() > 2 * kHciPrescanFromBytes);
        HciFrameDecoder decoder;
        decoder.feed(*encodeHciFrame(9, list));
        auto result = decoder.next();
        QVERIFY(result);
        const auto *frame = std::get_if<HciFrame>(&*result);
        QVERIFY2(frame, frame ? "" : std::get<HciDroppedFrame>(*result).detail.c_str());
        QCOMPARE(static_cast<const pb::GetObjectListResponse &>(*frame->message).objects_size(), 30000);
    }

    // Over a real socket: the server answers a request with the bomb, then with the real list. The
    // connection names the dropped frame, the request still gets its answer, and the heap never
    // held what the bomb would have become.
    void overASocketTheBombIsNamedAndTheAnswerArrives()
    {
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost));
        connect(&server, &QTcpServer::newConnection, this, [&server] {
            QTcpSocket *socket = server.nextPendingConnection();
            auto decoder = std::make_shared<HciFrameDecoder>();
            connect(socket, &QTcpSocket::readyRead, socket, [socket, decoder] {
                const QByteArray bytes = socket->readAll();
                decoder->feed(std::string_view(bytes.constData(), size_t(bytes.size())));
                while (auto request = decoder->next()) {
                    const int32_t id = std::get<HciFrame>(*request).header.instanceId;
                    const std::string bomb = encodeRawHciFrame(id, typeOf(pb::GetObjectListResponse()), emptyWrappers(4 << 20));
                    socket->write(bomb.data(), qint64(bomb.size()));
                    const std::string answer = *encodeHciFrame(id, vehicles(2));
                    socket->write(answer.data(), qint64(answer.size()));
                }
            });
        });
        HciConnection connection;
        QSignalSpy connected(&connection, &HciConnection::connected);
        connection.connectToServer(QStringLiteral("127.0.0.1"), server.serverPort());
        QVERIFY(connected.wait());
        QStringList reasons;
        connect(&connection, &HciConnection::frameDropped, this, [&](const QString &why) { reasons.append(why); });
        const qint64 heapBefore = test::heapBytesInUse();
        pb::GetObjectListRequest request;
        request.set_clientid(1);
        request.set_objecttype("Vehicle");
        HciReply *reply = connection.send(request);
        reply->setAutoDelete(false);
        std::unique_ptr<HciReply> kept(reply);
        QSignalSpy finished(reply, &HciReply::finished);
        QVERIFY(reply->isFinished() || finished.wait(30000));
        QVERIFY2(reply->isOk(), qPrintable(reply->error().toString()));
        QCOMPARE(reply->response<pb::GetObjectListResponse>().objects_size(), 2);
        QCOMPARE(reasons.size(), 1);
        QVERIFY2(reasons.first().contains(QLatin1String("too large once decoded")), qPrintable(reasons.first()));
        const qint64 grown = test::heapBytesInUse() - heapBefore;
        QVERIFY2(grown < (64 << 20), qPrintable(QString::number(grown))); // the bomb is 8 MiB, decoded it would be 2 GiB
        QCOMPARE(connection.framesDecodedAside(), quint64(1)); // the bomb was judged off this thread
    }

    // A big answer is decoded on another thread, and the small answer behind it in the stream still
    // finishes after it: the order the server wrote is the order the client sees.
    void aBigAnswerIsDecodedAsideAndKeepsItsPlace()
    {
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost));
        connect(&server, &QTcpServer::newConnection, this, [&server] {
            QTcpSocket *socket = server.nextPendingConnection();
            auto decoder = std::make_shared<HciFrameDecoder>();
            auto ids = std::make_shared<std::vector<int32_t>>();
            connect(socket, &QTcpSocket::readyRead, socket, [socket, decoder, ids] {
                const QByteArray bytes = socket->readAll();
                decoder->feed(std::string_view(bytes.constData(), size_t(bytes.size())));
                while (auto request = decoder->next())
                    ids->push_back(std::get<HciFrame>(*request).header.instanceId);
                if (ids->size() < 2)
                    return;
                const std::string big = *encodeHciFrame(ids->at(0), vehicles(30000));
                const std::string small = *encodeHciFrame(ids->at(1), vehicles(1));
                socket->write(big.data(), qint64(big.size()));
                socket->write(small.data(), qint64(small.size()));
                ids->clear();
            });
        });
        HciConnection connection;
        QSignalSpy connected(&connection, &HciConnection::connected);
        connection.connectToServer(QStringLiteral("127.0.0.1"), server.serverPort());
        QVERIFY(connected.wait());
        pb::GetObjectListRequest request;
        request.set_clientid(1);
        request.set_objecttype("Vehicle");
        std::unique_ptr<HciReply> big(connection.send(request));
        std::unique_ptr<HciReply> small(connection.send(request));
        big->setAutoDelete(false);
        small->setAutoDelete(false);
        QStringList order;
        connect(big.get(), &HciReply::finished, this, [&] { order << QStringLiteral("big"); });
        connect(small.get(), &HciReply::finished, this, [&] { order << QStringLiteral("small"); });
        QTRY_COMPARE_WITH_TIMEOUT(order.size(), 2, 30000);
        QCOMPARE(order, (QStringList{QStringLiteral("big"), QStringLiteral("small")}));
        QVERIFY2(big->isOk(), qPrintable(big->error().toString()));
        QCOMPARE(big->response<pb::GetObjectListResponse>().objects_size(), 30000);
        QCOMPARE(small->response<pb::GetObjectListResponse>().objects_size(), 1);
        QCOMPARE(connection.framesDecodedAside(), quint64(1));
        QCOMPARE(connection.framesDropped(), quint64(0));
    }
};

QTEST_MAIN(TestHciDecodedSize)
#include "tst_hcidecodedsize.moc"
