// HciDumpWriter on the SDK's vectors: one JSON line per frame, with the offsets, types and names the
// index lists, protobuf JSON that parses back to the same message, dropped frames with their reason,
// a truncated tail reported, passwords hidden, and the same output however the bytes are split.
#include "HciDumpWriter.h"
#include "TestData.h"
#include "HciMessageTypes.h"
#include "Messages.pb.h"

#include <google/protobuf/util/json_util.h>
#include <google/protobuf/util/message_differencer.h>
#include <nlohmann/json.hpp>

#include <QtTest>

#include <fstream>
#include <sstream>

using json = nlohmann::json;
using sortie::dump::HciDumpWriter;
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

std::vector<json> dump(const std::string &bytes, size_t chunk = 0, HciDumpWriter::Options options = {})
{
    std::ostringstream out;
    HciDumpWriter writer(out, options);
    if (chunk == 0)
        writer.feed(bytes);
    else
        for (size_t at = 0; at < bytes.size(); at += chunk)
            writer.feed(std::string_view(bytes).substr(at, chunk));
    writer.finish();
    std::vector<json> lines;
    std::istringstream in(out.str());
    for (std::string line; std::getline(in, line);)
        lines.push_back(json::parse(line));
    return lines;
}

} // namespace

class TestHciDump : public QObject
{
    Q_OBJECT

private slots:
    void everyVectorFrameBecomesOneLine()
    {
        std::string all;
        std::vector<const json *> entries;
        for (const auto &e : index())
            if (e.contains("file")) {
                all += readFile(e["file"]);
                entries.push_back(&e);
            }
        const auto lines = dump(all, 0, {true});
        QCOMPARE(lines.size(), entries.size());
        uint64_t offset = 0;
        for (size_t i = 0; i < lines.size(); ++i) {
            const json &line = lines[i];
            const json &e = *entries[i];
            QCOMPARE(line["offset"].get<uint64_t>(), offset);
            QCOMPARE(line["instanceId"].get<int>(), e["instanceId"].get<int>());
            QCOMPARE(line["type"].get<int>(), e["type"].get<int>());
            QCOMPARE(line["message"].get<std::string>(), e["message"].get<std::string>());
            // The JSON is protobuf JSON: it parses back into the very message the SDK encoded.
            std::unique_ptr<gpb::Message> fromDump(sortie::hci::HciMessageTypes::prototype(line["type"])->New());
            std::unique_ptr<gpb::Message> expected(fromDump->New());
            QVERIFY(gpb::util::JsonStringToMessage(line["json"].dump(), fromDump.get()).ok());
            QVERIFY(gpb::util::JsonStringToMessage(e["json"].dump(), expected.get()).ok());
            QVERIFY2(gpb::util::MessageDifferencer::Equals(*fromDump, *expected), e["file"].get<std::string>().c_str());
            offset += 16 + e["length"].get<uint64_t>();
        }
        // lowerCamelCase names, as the vectors use.
        QVERIFY(lines[0]["json"].contains("clientVersion"));
    }

    void droppedFramesAreLinesWithTheirReason()
    {
        for (const auto &e : index()) {
            if (!e.contains("stream"))
                continue;
            const auto lines = dump(readFile(e["stream"]));
            const json &frames = e["frames"];
            QCOMPARE(lines.size(), frames.size());
            for (size_t i = 0; i < frames.size(); ++i) {
                QCOMPARE(lines[i]["offset"].get<uint64_t>(), frames[i]["offset"].get<uint64_t>());
                QCOMPARE(lines[i]["type"].get<int>(), frames[i]["type"].get<int>());
                const bool dropped = frames[i]["expect"] == "dropped";
                QCOMPARE(lines[i].contains("dropped"), dropped);
                QCOMPARE(lines[i].contains("json"), !dropped);
                if (dropped)
                    QVERIFY(!lines[i]["detail"].get<std::string>().empty());
            }
        }
    }

    void splittingTheStreamChangesNothing()
    {
        const std::string bytes = readFile("stream-bad-frames.bin") + readFile("029-Notification.bin");
        const auto whole = dump(bytes);
        for (size_t chunk : {1, 7, 16, 100})
            QCOMPARE(dump(bytes, chunk), whole);
    }

    void aTruncatedTailIsReported()
    {
        const std::string frame = readFile("010-GetObjectListResponse.bin");
        auto lines = dump(readFile("002-AuthorizeHciResponse.bin") + frame.substr(0, 40));
        QCOMPARE(lines.size(), size_t(2));
        QCOMPARE(lines[1]["dropped"].get<std::string>(), std::string("truncated"));
        QCOMPARE(lines[1]["offset"].get<int>(), 24);
        QCOMPARE(lines[1]["message"].get<std::string>(), std::string("GetObjectListResponse"));
        QVERIFY(lines[1]["detail"].get<std::string>().find("24 bytes into a payload of 422") != std::string::npos);
        lines = dump(frame.substr(0, 5));
        QCOMPARE(lines.size(), size_t(1));
        QVERIFY(lines[0]["detail"].get<std::string>().find("less than a frame header") != std::string::npos);
    }

    void passwordsAreHiddenUnlessRevealed()
    {
        const std::string login = readFile("007-LoginRequest.bin");
        const auto hidden = dump(login);
        QCOMPARE(hidden[0]["json"]["userPassword"].get<std::string>(), std::string("***"));
        QCOMPARE(hidden[0]["json"]["userLogin"].get<std::string>(), std::string("admin"));
        const auto shown = dump(login, 0, {true});
        QCOMPARE(shown[0]["json"]["userPassword"].get<std::string>(), std::string("admin"));
    }
};

QTEST_APPLESS_MAIN(TestHciDump)
#include "tst_hcidump.moc"
