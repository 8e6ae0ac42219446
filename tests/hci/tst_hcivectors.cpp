// Decodes every frame the official UgCS SDK encoded (tests/data/hci-vectors) and re-encodes every
// client request byte for byte; streams yield exactly the decoded/dropped sequence the index lists,
// however the bytes are split.
#include "HciFrameCodec.h"
#include "TestData.h"
#include "HciMessageTypes.h"
#include "Messages.pb.h"

#include <google/protobuf/message.h>
#include <google/protobuf/util/field_comparator.h>
#include <google/protobuf/util/json_util.h>
#include <google/protobuf/util/message_differencer.h>
#include <nlohmann/json.hpp>

#include <QtTest>

#include <fstream>
#include <sstream>

using namespace sortie::hci;
using json = nlohmann::json;
namespace gpb = google::protobuf;

namespace {

std::string readFile(const std::string &name)
{
    std::ifstream in(std::string(sortieTestData()) + "/hci-vectors/" + name, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const json &index()
{
    static const json data = json::parse(readFile("index.json"));
    return data;
}

std::unique_ptr<gpb::Message> fromJson(int32_t type, const json &j)
{
    std::unique_ptr<gpb::Message> m(HciMessageTypes::prototype(type)->New());
    const auto status = gpb::util::JsonStringToMessage(j.dump(), m.get());
    if (!status.ok())
        qFatal("json does not parse: %s", status.ToString().c_str());
    return m;
}

bool equalNanAware(const gpb::Message &a, const gpb::Message &b, std::string *diff)
{
    gpb::util::DefaultFieldComparator comparator;
    comparator.set_treat_nan_as_equal(true);
    gpb::util::MessageDifferencer differ;
    differ.set_field_comparator(&comparator);
    differ.ReportDifferencesToString(diff);
    return differ.Compare(a, b);
}

std::vector<HciFrameDecoder::Result> decodeChunks(const std::string &bytes, const std::vector<size_t> &splits)
{
    HciFrameDecoder decoder;
    std::vector<HciFrameDecoder::Result> out;
    size_t from = 0;
    auto drain = [&] {
        while (auto r = decoder.next())
            out.push_back(std::move(*r));
    };
    for (size_t at : splits) {
        decoder.feed(std::string_view(bytes).substr(from, at - from));
        drain();
        from = at;
    }
    decoder.feed(std::string_view(bytes).substr(from));
    drain();
    return out;
}

// A compact, comparable description of a decode result sequence.
std::string describe(const std::vector<HciFrameDecoder::Result> &results)
{
    std::string s;
    for (const auto &r : results) {
        if (const auto *f = std::get_if<HciFrame>(&r))
            s += "D@" + std::to_string(f->offset) + ":" + std::to_string(f->header.instanceId) + "|"
                 + f->message->ShortDebugString() + ";";
        else {
            const auto &d = std::get<HciDroppedFrame>(r);
            s += "X@" + std::to_string(d.offset) + ":" + toString(d.reason) + ";";
        }
    }
    return s;
}

} // namespace

class TestHciVectors : public QObject
{
    Q_OBJECT

private slots:
    void typeTableIsABijection()
    {
        QCOMPARE(HciMessageTypes::count(), size_t(204));
        std::set<const gpb::Descriptor *> seen;
        for (size_t i = 0; i < HciMessageTypes::count(); ++i) {
            const int32_t n = HciMessageTypes::numberAt(i);
            const auto *p = HciMessageTypes::prototype(n);
            QVERIFY(p);
            QVERIFY(seen.insert(p->GetDescriptor()).second);
            QCOMPARE(HciMessageTypes::number(p->GetDescriptor()).value(), n);
        }
        QCOMPARE(HciMessageTypes::name(22), std::string_view("LoginRequest"));
        QVERIFY(!HciMessageTypes::prototype(7));
        QVERIFY(!HciMessageTypes::prototype(9999));
    }

    void frames_data()
    {
        QTest::addColumn<int>("entry");
        for (size_t i = 0; i < index().size(); ++i)
            if (index()[i].contains("file") && !index()[i].contains("stream"))
                QTest::newRow(index()[i]["file"].get<std::string>().c_str()) << int(i);
    }

    void frames()
    {
        QFETCH(int, entry);
        const json &e = index()[entry];
        const std::string bytes = readFile(e["file"]);
        QCOMPARE(bytes.size(), kHciHeaderSize + e["length"].get<size_t>());

        HciFrameDecoder decoder;
        decoder.feed(bytes);
        auto result = decoder.next();
        QVERIFY(result);
        if (const auto *dropped = std::get_if<HciDroppedFrame>(&*result))
            QFAIL(dropped->detail.c_str());
        const auto &frame = std::get<HciFrame>(*result);
        QCOMPARE(frame.header.instanceId, e["instanceId"].get<int32_t>());
        QCOMPARE(frame.header.type, e["type"].get<int32_t>());
        QCOMPARE(std::string(frame.message->GetDescriptor()->name()), e["message"].get<std::string>());
        QVERIFY(!decoder.next());
        QCOMPARE(decoder.buffered(), size_t(0));

        const auto expected = fromJson(frame.header.type, e["json"]);
        std::string diff;
        QVERIFY2(equalNanAware(*expected, *frame.message, &diff), diff.c_str());

        // Client requests must come out of our encoder byte for byte.
        if (e["direction"] == "client->server" && !e.value("decodeOnly", false)) {
            const auto encoded = encodeHciFrame(e["instanceId"], *expected);
            QVERIFY(encoded);
            QCOMPARE(QByteArray::fromStdString(*encoded).toHex(), QByteArray::fromStdString(bytes).toHex());
        }
        // And every frame that round-trips in the SDK round-trips here too.
        if (e.value("roundTrip", false)) {
            const auto again = encodeHciFrame(e["instanceId"], *frame.message);
            QVERIFY(again);
            QCOMPARE(QByteArray::fromStdString(*again).toHex(), QByteArray::fromStdString(bytes).toHex());
        }
    }

    void splitAtEveryByte_data()
    {
        QTest::addColumn<std::string>("file");
        for (const auto &e : index())
            QTest::newRow(e.value("file", e.value("stream", "")).c_str()) << e.value("file", e.value("stream", ""));
    }

    void splitAtEveryByte()
    {
        QFETCH(std::string, file);
        const std::string bytes = readFile(file);
        const std::string whole = describe(decodeChunks(bytes, {}));
        for (size_t at = 1; at < bytes.size(); ++at)
            QCOMPARE(describe(decodeChunks(bytes, {at})), whole);
        // Byte by byte.
        std::vector<size_t> every;
        for (size_t at = 1; at < bytes.size(); ++at)
            every.push_back(at);
        QCOMPARE(describe(decodeChunks(bytes, every)), whole);
    }

    void streams_data()
    {
        QTest::addColumn<int>("entry");
        for (size_t i = 0; i < index().size(); ++i)
            if (index()[i].contains("stream"))
                QTest::newRow(index()[i]["stream"].get<std::string>().c_str()) << int(i);
    }

    void streams()
    {
        QFETCH(int, entry);
        const json &e = index()[entry];
        const std::string bytes = readFile(e["stream"]);
        QCOMPARE(bytes.size(), e["length"].get<size_t>());
        const auto results = decodeChunks(bytes, {});
        const json &frames = e["frames"];
        QCOMPARE(results.size(), frames.size());
        for (size_t i = 0; i < frames.size(); ++i) {
            const json &f = frames[i];
            if (f["expect"] == "decoded") {
                const auto *frame = std::get_if<HciFrame>(&results[i]);
                QVERIFY2(frame, f["why"].get<std::string>().c_str());
                QCOMPARE(frame->offset, f["offset"].get<uint64_t>());
                QCOMPARE(frame->header.instanceId, f["instanceId"].get<int32_t>());
                QCOMPARE(std::string(frame->message->GetDescriptor()->name()), f["message"].get<std::string>());
                const json &body = f.contains("file") ? [&]() -> const json & {
                    for (const auto &x : index())
                        if (x.value("file", "") == f["file"])
                            return x["json"];
                    return f;
                }() : f["json"];
                const auto expected = fromJson(frame->header.type, body);
                std::string diff;
                QVERIFY2(equalNanAware(*expected, *frame->message, &diff), diff.c_str());
            } else {
                const auto *dropped = std::get_if<HciDroppedFrame>(&results[i]);
                QVERIFY2(dropped, f["why"].get<std::string>().c_str());
                QCOMPARE(dropped->offset, f["offset"].get<uint64_t>());
                QCOMPARE(dropped->header.type, f["type"].get<int32_t>());
                QVERIFY(!dropped->detail.empty());
            }
        }
    }

    void badLengthResynchronisesOnNextHeader()
    {
        // A good frame, a header claiming 2 GiB, garbage, then two good frames: the decoder reports the
        // bad length, skips to the next plausible header, and loses neither good frame around it.
        const std::string good = readFile("002-AuthorizeHciResponse.bin");
        const std::string login = readFile("008-LoginResponse.bin");
        std::string bad = encodeRawHciFrame(5, 21, "");
        bad[12] = 0x7f; bad[13] = char(0xff); bad[14] = char(0xff); bad[15] = char(0xff);
        const std::string stream = good + bad + "GET / HTTP/1.1\r\nHPHP\x00\x01" + login + good;
        for (size_t split : {size_t(0), size_t(1), size_t(17), size_t(30), size_t(50), stream.size() - 3}) {
            const auto results = decodeChunks(stream, split ? std::vector<size_t>{split} : std::vector<size_t>{});
            QCOMPARE(results.size(), size_t(4));
            QVERIFY(std::holds_alternative<HciFrame>(results[0]));
            const auto &dropped = std::get<HciDroppedFrame>(results[1]);
            QCOMPARE(dropped.reason, HciDropReason::BadLength);
            QCOMPARE(dropped.offset, uint64_t(good.size()));
            const auto &second = std::get<HciFrame>(results[2]);
            QCOMPARE(second.offset, uint64_t(stream.size() - good.size() - login.size()));
            QCOMPARE(std::string(second.message->GetDescriptor()->name()), std::string("LoginResponse"));
            QVERIFY(std::holds_alternative<HciFrame>(results[3]));
        }
    }

    void negativeLengthAndMemoryStaysBounded()
    {
        // A negative length, then 10 MB of garbage with no header: the decoder keeps at most a header's worth.
        HciFrameDecoder decoder;
        std::string bad = encodeRawHciFrame(1, 21, "");
        bad[12] = char(0xff);
        decoder.feed(bad);
        auto r = decoder.next();
        QVERIFY(r && std::holds_alternative<HciDroppedFrame>(*r));
        QCOMPARE(std::get<HciDroppedFrame>(*r).reason, HciDropReason::BadLength);
        const std::string garbage(64 * 1024, 'x');
        for (int i = 0; i < 160; ++i) {
            decoder.feed(garbage);
            QVERIFY(!decoder.next());
            QVERIFY(decoder.buffered() < kHciHeaderSize);
        }
        decoder.feed(readFile("002-AuthorizeHciResponse.bin"));
        r = decoder.next();
        QVERIFY(r && std::holds_alternative<HciFrame>(*r));
        QCOMPARE(decoder.framesDecoded(), uint64_t(1));
        QCOMPARE(decoder.framesDropped(), uint64_t(1));
    }

    void largeLengthWaitsWithoutReserving()
    {
        // A plausible 64 MiB header is honoured (the SDK accepts exactly 64 MiB) but nothing is reserved for it.
        HciFrameDecoder decoder;
        std::string header = encodeRawHciFrame(1, 21, "");
        header[12] = 0x04; header[13] = 0; header[14] = 0; header[15] = 0;
        decoder.feed(header);
        QVERIFY(!decoder.next());
        QCOMPARE(decoder.buffered(), kHciHeaderSize);
    }

    void encoderRefusesWhatAPeerWouldDrop()
    {
        com::ugcs::ucs::proto::LoginRequest incomplete; // clientId is required
        incomplete.set_userlogin("admin");
        QVERIFY(!encodeHciFrame(0, incomplete));
        com::ugcs::ucs::proto::Vehicle notAMessage; // a domain type has no HCI type number
        QVERIFY(!encodeHciFrame(0, notAMessage));
    }
};

QTEST_APPLESS_MAIN(TestHciVectors)
#include "tst_hcivectors.moc"
