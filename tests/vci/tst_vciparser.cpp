// VciParser: every message kind, both body framings, every chunk split point.
#include "VciDumpWriter.h"
#include "VciTestStreams.h"
#include "VciWriter.h"

#include <QtTest>

#include <sstream>

using nlohmann::json;
using namespace sortie::vci;
using namespace sortie::vci::test;

namespace {

const VciMessage &msg(const std::vector<VciParser::Result> &r, size_t i)
{
    return std::get<VciMessage>(r.at(i));
}

// A stream with one message of every kind and both framings.
std::string mixedStream()
{
    return "GET /vehicle VCI/1.0\r\n\r\n"
           "VCI/1.0 200 OK\r\nContent-Type: application/json\r\nContent-Length: 29\r\n\r\n{\"id\":\"sim-1\",\"name\":\"Alpha\"}"
           "SUBSCRIBE /telemetry/position VCI/1.0\r\n\r\n"
           "NOTIFY /telemetry/position VCI/1.0\r\nContent-Type: application/json\r\n\r\n"
           "{\"latitude\":0.99442,\"note\":\"a {brace} and \\\"quote\\\"\",\"list\":[[1,2],[3,[4]]]}"
           "VCI/1.0 200 OK\r\n\r\n"
           "NOTIFY /state/armed VCI/1.0\r\ncontent-type: application/json\r\n\r\ntrue"
           "NOTIFY /parameters/cruise_speed VCI/1.0\r\nContent-Type: application/json\r\n\r\n8.5 "
           "PUT /state/mode VCI/1.0\r\nCONTENT-TYPE: application/json\r\nCONTENT-LENGTH: 6\r\n\r\n\"auto\""
           "VCI/1.0 501 Not Implemented\r\n\r\n"
           "UNSUBSCRIBE * VCI/1.0\r\n\r\n";
}

} // namespace

class TstVciParser : public QObject
{
    Q_OBJECT
private slots:
    void everyMessageKind();
    void eachJsonKindAsBody_data();
    void eachJsonKindAsBody();
    void notifyWhileGetOutstanding();
    void everySplitPoint();
    void byteByByte();
    void rawBodyByLength();
    void lenientLineEndsAndEmptyLines();
    void offsetsAndSizes();
    void writerRoundTrip_data();
    void writerRoundTrip();
    void dumpLines();
    void dumpWriter();
};

void TstVciParser::everyMessageKind()
{
    const auto r = parseAll(mixedStream());
    QCOMPARE(r.size(), size_t(10));
    for (const auto &x : r)
        QVERIFY2(std::holds_alternative<VciMessage>(x), vciDumpLine(x).dump().c_str());

    QVERIFY(msg(r, 0).isRequest());
    QVERIFY(msg(r, 0).verb == VciVerb::Get);
    QCOMPARE(msg(r, 0).uri, std::string("/vehicle"));
    QVERIFY(!msg(r, 0).hasBody);

    QVERIFY(msg(r, 1).isResponse());
    QCOMPARE(msg(r, 1).status, 200);
    QCOMPARE(msg(r, 1).reason, std::string("OK"));
    QCOMPARE(msg(r, 1).body, json({{"id", "sim-1"}, {"name", "Alpha"}}));
    QCOMPARE(msg(r, 1).headers.value("content-length").value(), std::string_view("29"));

    QVERIFY(msg(r, 2).verb == VciVerb::Subscribe);
    QVERIFY(msg(r, 3).verb == VciVerb::Notify);
    QCOMPARE(msg(r, 3).body["note"], json("a {brace} and \"quote\""));
    QCOMPARE(msg(r, 3).body["list"], json::parse("[[1,2],[3,[4]]]"));
    QCOMPARE(msg(r, 4).status, 200);
    QVERIFY(!msg(r, 4).hasBody);
    QCOMPARE(msg(r, 5).body, json(true));
    QCOMPARE(msg(r, 6).body, json(8.5));
    QVERIFY(msg(r, 7).verb == VciVerb::Put);
    QCOMPARE(msg(r, 7).body, json("auto"));
    QCOMPARE(msg(r, 8).status, 501);
    QCOMPARE(msg(r, 8).reason, std::string("Not Implemented"));
    QVERIFY(msg(r, 9).verb == VciVerb::Unsubscribe);
    QCOMPARE(msg(r, 9).uri, std::string("*"));
}

void TstVciParser::eachJsonKindAsBody_data()
{
    QTest::addColumn<QByteArray>("body");
    QTest::addColumn<bool>("byLength");
    const char *bodies[] = {"{\"a\":{\"b\":[1,{\"c\":null}]}}", "[[[]],[[1],[2,[3]]]]", "\"text with {} and \\\"\\\\\"",
                            "true", "false", "null", "0", "-12", "3.14159", "1e-7", "18446744073709551615", "{}", "[]", "\"\""};
    for (const char *b : bodies) {
        QTest::newRow((std::string("json ") + b).c_str()) << QByteArray(b) << false;
        QTest::newRow((std::string("length ") + b).c_str()) << QByteArray(b) << true;
    }
}

void TstVciParser::eachJsonKindAsBody()
{
    QFETCH(QByteArray, body);
    QFETCH(bool, byLength);
    const json expected = json::parse(body.toStdString());
    std::string text = body.toStdString();
    std::string stream = "NOTIFY /x VCI/1.0\r\nContent-Type: application/json\r\n";
    if (byLength)
        stream += "Content-Length: " + std::to_string(text.size()) + "\r\n";
    else if (expected.is_number())
        text += " "; // the one whitespace character that ends a bare number
    stream += "\r\n" + text + "GET /next VCI/1.0\r\n\r\n";
    for (size_t chunk : {size_t(1), size_t(5), stream.size()}) {
        std::vector<size_t> cuts;
        for (size_t c = chunk; c < stream.size(); c += chunk)
            cuts.push_back(c);
        const auto r = parseChunked(stream, cuts);
        QCOMPARE(r.size(), size_t(2));
        QVERIFY2(std::holds_alternative<VciMessage>(r[0]), vciDumpLine(r[0]).dump().c_str());
        QVERIFY(msg(r, 0).jsonBody);
        QCOMPARE(msg(r, 0).body, expected);
        QCOMPARE(msg(r, 0).body.type(), expected.type());
        QCOMPARE(msg(r, 1).uri, std::string("/next"));
    }
}

void TstVciParser::notifyWhileGetOutstanding()
{
    // We sent GET /vehicle; before its answer the vehicle sends two NOTIFYs. Order is kept, each once.
    const std::string stream = "NOTIFY /state/mode VCI/1.0\r\nContent-Type: application/json\r\n\r\n\"hold\""
                               "NOTIFY /state/armed VCI/1.0\r\nContent-Type: application/json\r\n\r\nfalse"
                               "VCI/1.0 200 OK\r\nContent-Type: application/json\r\n\r\n{\"id\":\"v\"}";
    const auto r = parseAll(stream);
    QCOMPARE(r.size(), size_t(3));
    QVERIFY(msg(r, 0).verb == VciVerb::Notify);
    QCOMPARE(msg(r, 0).body, json("hold"));
    QCOMPARE(msg(r, 1).body, json(false));
    QVERIFY(msg(r, 2).isResponse());
    QCOMPARE(msg(r, 2).body["id"], json("v"));
}

void TstVciParser::everySplitPoint()
{
    const std::string stream = mixedStream();
    const std::string whole = describe(parseAll(stream));
    for (size_t cut = 1; cut < stream.size(); ++cut) {
        const std::string split = describe(parseChunked(stream, {cut}));
        if (split != whole)
            QFAIL(qPrintable(QStringLiteral("split at %1 differs:\n%2\nvs\n%3").arg(cut).arg(split.c_str(), whole.c_str())));
    }
    // Three pieces, every pair of cuts on a coarser grid.
    for (size_t a = 1; a < stream.size(); a += 7) {
        for (size_t b = a + 1; b < stream.size(); b += 11)
            QCOMPARE(describe(parseChunked(stream, {a, b})), whole);
    }
}

void TstVciParser::byteByByte()
{
    const std::string stream = mixedStream();
    std::vector<size_t> cuts;
    for (size_t i = 1; i < stream.size(); ++i)
        cuts.push_back(i);
    QCOMPARE(describe(parseChunked(stream, cuts)), describe(parseAll(stream)));
}

void TstVciParser::rawBodyByLength()
{
    static const char bytes[] = "PUT /firmware VCI/1.0\r\nContent-Type: application/octet-stream\r\nContent-Length: 5\r\n\r\n"
                                "\x00\x01{\r\nGET /a VCI/1.0\r\n\r\n";
    const auto r = parseAll(std::string(bytes, sizeof bytes - 1));
    QCOMPARE(r.size(), size_t(2));
    QVERIFY(msg(r, 0).hasBody);
    QVERIFY(!msg(r, 0).jsonBody);
    QCOMPARE(msg(r, 0).rawBody, std::string("\x00\x01{\r\n", 5));
    QCOMPARE(msg(r, 1).uri, std::string("/a"));
}

void TstVciParser::lenientLineEndsAndEmptyLines()
{
    const auto r = parseAll("\r\n\r\nGET /a VCI/1.0\n\nVCI/1.0 200 OK\r\n\r\n\r\nGET /b VCI/1.0\r\nX-Note:  spaced value \t\r\n\r\n");
    QCOMPARE(r.size(), size_t(3));
    QCOMPARE(msg(r, 0).uri, std::string("/a"));
    QCOMPARE(msg(r, 1).status, 200);
    QCOMPARE(msg(r, 2).headers.value("x-note").value(), std::string_view("spaced value"));
}

void TstVciParser::offsetsAndSizes()
{
    const std::string a = "GET /a VCI/1.0\r\n\r\n";
    const std::string b = "NOTIFY /b VCI/1.0\r\nContent-Type: application/json\r\n\r\n12 ";
    const auto r = parseAll(a + b + a);
    QCOMPARE(r.size(), size_t(3));
    QCOMPARE(msg(r, 0).offset, uint64_t(0));
    QCOMPARE(msg(r, 0).size, uint64_t(a.size()));
    QCOMPARE(msg(r, 1).offset, uint64_t(a.size()));
    QCOMPARE(msg(r, 1).size, uint64_t(b.size()));
    QCOMPARE(msg(r, 2).offset, uint64_t(a.size() + b.size()));
}

void TstVciParser::writerRoundTrip_data()
{
    QTest::addColumn<int>("framing");
    QTest::newRow("content-length") << int(VciFraming::ContentLength);
    QTest::newRow("json-only") << int(VciFraming::JsonOnly);
}

void TstVciParser::writerRoundTrip()
{
    QFETCH(int, framing);
    const VciWriter w{VciFraming(framing)};
    const std::vector<json> bodies = {json::object({{"a", 1}}), json::array({1, "x", nullptr}), json("s {}\""), json(true),
                                      json(nullptr), json(-4), json(2.5), json(7u)};
    std::string stream;
    for (const json &b : bodies) {
        w.appendRequest(stream, VciVerb::Put, "/p", &b);
        w.appendResponse(stream, 200, {}, &b);
    }
    w.appendRequest(stream, VciVerb::Unsubscribe, "*");
    VciHeaders extra;
    extra.add("X-Trace", "7");
    w.appendResponse(stream, 400, "Bad Request", nullptr, &extra);
    const auto r = parseAll(stream);
    QCOMPARE(r.size(), bodies.size() * 2 + 2);
    for (size_t i = 0; i < bodies.size(); ++i) {
        QCOMPARE(msg(r, 2 * i).body, bodies[i]);
        QCOMPARE(msg(r, 2 * i + 1).body, bodies[i]);
        QCOMPARE(msg(r, 2 * i + 1).status, 200);
    }
    QCOMPARE(msg(r, r.size() - 2).uri, std::string("*"));
    QCOMPARE(msg(r, r.size() - 1).status, 400);
    QCOMPARE(msg(r, r.size() - 1).headers.value("X-Trace").value(), std::string_view("7"));
    QVERIFY(VciWriter::isValidUri("/a/b?c=1"));
    QVERIFY(!VciWriter::isValidUri("a"));
    QVERIFY(!VciWriter::isValidUri("/a b"));
}

void TstVciParser::dumpLines()
{
    const auto r = parseAll("NOTIFY /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n[1]"
                            "FETCH /x VCI/1.0\r\n\r\n");
    QCOMPARE(r.size(), size_t(2));
    const json m = vciDumpLine(r[0]);
    QCOMPARE(m["kind"], json("request"));
    QCOMPARE(m["verb"], json("NOTIFY"));
    QCOMPARE(m["uri"], json("/x"));
    QCOMPARE(m["offset"], json(0));
    QCOMPARE(m["body"], json::array({1}));
    QCOMPARE(m["headers"][0][0], json("Content-Type"));
    const json e = vciDumpLine(r[1]);
    QCOMPARE(e["kind"], json("error"));
    QCOMPARE(e["error"], json("unknown verb"));
    QCOMPARE(e["verb"], json("FETCH"));
    QCOMPARE(e["reply"], json(501));
    QCOMPARE(e["offset"], m["size"]);
}

void TstVciParser::dumpWriter()
{
    std::ostringstream out;
    VciDumpWriter writer(out);
    const std::string stream = mixedStream() + "PUT /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n[1,]\r\n"
                               + "NOTIFY /cut VCI/1.0\r\nContent-Type: application/json\r\n\r\n{\"a\":";
    for (size_t i = 0; i < stream.size(); i += 13)
        writer.feed(std::string_view(stream).substr(i, 13));
    writer.finish();
    std::vector<json> lines;
    std::istringstream in(out.str());
    for (std::string line; std::getline(in, line);)
        lines.push_back(json::parse(line));
    QCOMPARE(lines.size(), size_t(12)); // 10 messages, the bad PUT, the cut NOTIFY
    QCOMPARE(lines[3]["verb"], json("NOTIFY"));
    QCOMPARE(lines[10]["kind"], json("error"));
    QCOMPARE(lines[10]["error"], json("bad JSON"));
    QCOMPARE(lines[11]["error"], json("truncated"));
    QCOMPARE(lines[11]["offset"], json(stream.find("NOTIFY /cut")));
    QCOMPARE(writer.messages(), uint64_t(10));
    QCOMPARE(writer.errors(), uint64_t(2));
}

QTEST_GUILESS_MAIN(TstVciParser)
#include "tst_vciparser.moc"
