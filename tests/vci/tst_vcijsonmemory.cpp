// What a VCI JSON body takes in memory (issue 36): a 16 MiB body of `[[],[],…]` or `[{},{},…]` is
// three bytes an element on the wire and far more as a DOM. The reader counts what it builds, that
// count follows the allocator's own, and a body past VciLimits::maxDecodedBytes is refused with its
// reason, what was built is freed at once, and the next message reads as before.
#include "ProcessStats.h"
#include "VciJsonReader.h"
#include "VciParser.h"

#include <QtTest>

using nlohmann::json;
using namespace sortie;
using namespace sortie::vci;

namespace {

std::string repeated(const std::string &element, size_t count)
{
    std::string text = "[";
    text.reserve(count * (element.size() + 1) + 2);
    for (size_t i = 0; i < count; ++i) {
        if (i)
            text += ',';
        text += element;
    }
    text += ']';
    return text;
}

// A mission as a vehicle sends it: waypoints with positions, speeds and actions.
std::string mission(int waypoints)
{
    json route = json::array();
    for (int i = 0; i < waypoints; ++i)
        route.push_back({{"latitude", 56.95 + i * 1e-5}, {"longitude", 24.1 + i * 1e-5}, {"altitude", 40.0 + i % 7},
                         {"speed", 8.5}, {"type", "waypoint"}, {"actions", json::array({{{"kind", "camera_trigger"}, {"interval_s", 2}}})}});
    return json{{"name", "Riga port survey, northern block"}, {"waypoints", route}}.dump();
}

std::string body(const std::string &what)
{
    if (what == "empty arrays")
        return repeated("[]", 200000);
    if (what == "empty objects")
        return repeated("{}", 200000);
    if (what == "empty strings")
        return repeated("\"\"", 200000);
    if (what == "long strings")
        return repeated("\"" + std::string(40, 'x') + "\"", 50000);
    if (what == "zeros")
        return repeated("0", 300000);
    return mission(20000);
}

} // namespace

class TstVciJsonMemory : public QObject
{
    Q_OBJECT
private slots:
    void theCountFollowsTheAllocator_data()
    {
        QTest::addColumn<QString>("what");
        for (const char *what : {"empty arrays", "empty objects", "empty strings", "long strings", "zeros", "a mission"})
            QTest::newRow(what) << QString::fromLatin1(what);
    }

    void theCountFollowsTheAllocator()
    {
        QFETCH(QString, what);
        const std::string text = body(what.toStdString());
        const qint64 before = test::heapBytesInUse();
        VciJsonReader reader(256, 64 << 20, 512, size_t(1) << 40);
        QCOMPARE(reader.feed(text.data(), text.size()), text.size());
        QCOMPARE(reader.status(), VciJsonReader::Status::Done);
        const double held = double(test::heapBytesInUse() - before);
        const double counted = double(reader.decodedBytes());
        qInfo("%s: %zu bytes of JSON, counted %.0f, the allocator holds %.0f", qPrintable(what), text.size(), counted, held);
        // Near enough to bound by: never far under what is really held, never far over.
        QVERIFY2(counted > 0.7 * held && counted < 2.5 * held, qPrintable(QStringLiteral("%1 vs %2").arg(counted).arg(held)));
    }

    void aBodyTooLargeOnceReadIsRefusedAndFreed()
    {
        VciLimits limits;
        limits.maxDecodedBytes = 64 << 20;
        VciParser parser(limits);
        const std::string bomb = repeated("[]", (16 << 20) / 3 - 1); // just under the 16 MiB body limit
        const qint64 before = test::heapBytesInUse();
        parser.feed("NOTIFY /telemetry/position VCI/1.0\r\nContent-Type: application/json\r\nContent-Length: "
                    + std::to_string(bomb.size()) + "\r\n\r\n");
        parser.feed(bomb);
        parser.feed("NOTIFY /state/armed VCI/1.0\r\nContent-Type: application/json\r\n\r\ntrue");
        auto first = parser.next();
        QVERIFY(first);
        const auto *error = std::get_if<VciParseError>(&*first);
        QVERIFY(error);
        QVERIFY2(error->code == VciErrorCode::BodyTooLarge, error->message.c_str());
        QVERIFY2(error->message.find("more than 64 MiB of memory") != std::string::npos, error->message.c_str());
        // What the reader built before it stopped is gone; the input buffer is what remains.
        const qint64 held = test::heapBytesInUse() - before;
        QVERIFY2(held < qint64(bomb.size()) * 3, qPrintable(QString::number(held)));
        auto second = parser.next();
        QVERIFY(second);
        const auto *message = std::get_if<VciMessage>(&*second);
        QVERIFY(message);
        QCOMPARE(message->body, json(true));
    }

    void aRealMissionOfTheSameSizeStillReads()
    {
        const std::string text = mission(60000);
        QVERIFY(text.size() > (8 << 20));
        VciParser parser;
        parser.feed("VCI/1.0 200 OK\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(text.size())
                    + "\r\n\r\n" + text);
        auto result = parser.next();
        QVERIFY(result);
        const auto *message = std::get_if<VciMessage>(&*result);
        QVERIFY2(message, message ? "" : std::get<VciParseError>(*result).message.c_str());
        QCOMPARE(message->body.at("waypoints").size(), size_t(60000));
    }
};

QTEST_MAIN(TstVciJsonMemory)
#include "tst_vcijsonmemory.moc"
