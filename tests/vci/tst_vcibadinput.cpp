// VciParser on bad input: each case is reported once, with the status the peer gets, and the next
// message is read. Memory stays within the limits however much garbage arrives.
#include "VciTestStreams.h"

#include <QtTest>

#include <random>

using nlohmann::json;
using namespace sortie::vci;
using namespace sortie::vci::test;

namespace {

const std::string kNext = "GET /next VCI/1.0\r\n\r\n";

// Parses `bad` followed by a good message, whole and byte by byte; both must give one error with
// `code` and `reply`, then the good message.
void expectRecovery(const std::string &bad, VciErrorCode code, int reply, VciLimits limits = {})
{
    const std::string stream = bad + kNext;
    std::vector<size_t> everyByte;
    for (size_t i = 1; i < stream.size(); ++i)
        everyByte.push_back(i);
    for (const auto &r : {parseAll(stream, limits), parseChunked(stream, everyByte, limits)}) {
        QVERIFY2(r.size() == 2, describe(r).c_str());
        QVERIFY2(std::holds_alternative<VciParseError>(r[0]), describe(r).c_str());
        const auto &e = std::get<VciParseError>(r[0]);
        QVERIFY2(e.code == code, describe(r).c_str());
        QCOMPARE(e.replyStatus(), reply);
        QVERIFY(!e.message.empty());
        QCOMPARE(e.offset, uint64_t(0));
        QVERIFY2(std::holds_alternative<VciMessage>(r[1]), describe(r).c_str());
        QCOMPARE(describe(r).find("/next") != std::string::npos, true);
        QCOMPARE(std::get<VciMessage>(r[1]).uri, std::string("/next"));
    }
}

} // namespace

class TstVciBadInput : public QObject
{
    Q_OBJECT
private slots:
    void malformedStartLines();
    void unknownVerbGets501();
    void badUriAndVersion();
    void badHeaders();
    void badJsonBodyByLength();
    void badJsonBodyWithoutLength();
    void badContentLength();
    void lineTooLong();
    void tooManyHeaders();
    void bodyTooLarge();
    void missingEmptyLine();
    void brokenResponseAndNotifyGetNoReply();
    void garbageKeepsMemoryBounded();
    void randomNoiseNeverCrashes();
};

void TstVciBadInput::malformedStartLines()
{
    expectRecovery("GET\r\n\r\n", VciErrorCode::BadStartLine, 400);
    expectRecovery("GET  /x VCI/1.0\r\n\r\n", VciErrorCode::BadStartLine, 400);
    expectRecovery("hello world\r\n\r\n", VciErrorCode::BadStartLine, 400);
    expectRecovery("G{T /x VCI/1.0\r\n\r\n", VciErrorCode::BadStartLine, 400);
    // A bad start line with a body: the body is still framed by its headers and skipped exactly.
    expectRecovery("GET /x VCI/1.0 extra\r\nContent-Type: application/json\r\n\r\n{\"GET /y VCI/1.0\":1}",
                   VciErrorCode::BadStartLine, 400);
}

void TstVciBadInput::unknownVerbGets501()
{
    expectRecovery("DELETE /mission VCI/1.0\r\n\r\n", VciErrorCode::UnknownVerb, 501);
    expectRecovery("get /x VCI/1.0\r\nContent-Type: application/json\r\nContent-Length: 2\r\n\r\n{}",
                   VciErrorCode::UnknownVerb, 501);
    const auto r = parseAll("POST /x VCI/1.0\r\n\r\n");
    QCOMPARE(std::get<VciParseError>(r.at(0)).verb, std::string("POST"));
    QCOMPARE(std::get<VciParseError>(r.at(0)).uri, std::string("/x"));
}

void TstVciBadInput::badUriAndVersion()
{
    expectRecovery("GET x VCI/1.0\r\n\r\n", VciErrorCode::BadUri, 400);
    expectRecovery("GET * VCI/1.0\r\n\r\n", VciErrorCode::BadUri, 400);
    expectRecovery("GET /\x01 VCI/1.0\r\n\r\n", VciErrorCode::BadUri, 400);
    expectRecovery("GET /x VCI/2.0\r\n\r\n", VciErrorCode::UnsupportedVersion, 400);
    expectRecovery("GET /x HTTP/1.1\r\n\r\n", VciErrorCode::BadStartLine, 400);
    expectRecovery("VCI/1.1 200 OK\r\n\r\n", VciErrorCode::UnsupportedVersion, 0);
    expectRecovery("VCI/1.0 2000 OK\r\n\r\n", VciErrorCode::BadStartLine, 0);
    expectRecovery("VCI/1.0 99 Low\r\n\r\n", VciErrorCode::BadStartLine, 0);
}

void TstVciBadInput::badHeaders()
{
    expectRecovery("GET /x VCI/1.0\r\nno colon here\r\n\r\n", VciErrorCode::BadHeader, 400);
    expectRecovery("GET /x VCI/1.0\r\n: empty name\r\n\r\n", VciErrorCode::BadHeader, 400);
    expectRecovery("GET /x VCI/1.0\r\nBad Name: v\r\n\r\n", VciErrorCode::BadHeader, 400);
    expectRecovery("GET /x VCI/1.0\r\nX: a\x01z\r\n\r\n", VciErrorCode::BadHeader, 400);
}

void TstVciBadInput::badJsonBodyByLength()
{
    // The length is trusted: exactly the body is skipped, even when it looks like messages.
    const std::string body = "{\"a\":}\r\nGET /trap VCI/1.0\r\n\r\n";
    expectRecovery("PUT /x VCI/1.0\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(body.size())
                       + "\r\n\r\n" + body,
                   VciErrorCode::BadJson, 400);
    expectRecovery("PUT /x VCI/1.0\r\nContent-Type: application/json\r\nContent-Length: 7\r\n\r\n[1] [2]", VciErrorCode::BadJson, 400);
    expectRecovery("PUT /x VCI/1.0\r\nContent-Type: application/json\r\nContent-Length: 3\r\n\r\n[1,", VciErrorCode::BadJson, 400);
}

void TstVciBadInput::badJsonBodyWithoutLength()
{
    // The end is unknown: the parser skips to the next start line, wherever the JSON broke.
    expectRecovery("PUT /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n{\"a\": nope}\r\n", VciErrorCode::BadJson, 400);
    expectRecovery("PUT /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n[1, 2", VciErrorCode::BadJson, 400);
    expectRecovery("PUT /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n\"open string\r\n", VciErrorCode::BadJson, 400);
    expectRecovery("PUT /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n42}\r\n", VciErrorCode::BadJson, 400);
    expectRecovery("PUT /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n{\"k\":\"\\q\"}\r\njunk line\r\n", VciErrorCode::BadJson, 400);
    const auto r = parseAll("PUT /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n{\"a\": nope}\r\nmore junk\r\n" + kNext);
    const auto &e = std::get<VciParseError>(r.at(0));
    QVERIFY2(e.message.find("body byte 7") != std::string::npos, e.message.c_str());
    QCOMPARE(e.uri, std::string("/x"));
}

void TstVciBadInput::badContentLength()
{
    expectRecovery("PUT /x VCI/1.0\r\nContent-Type: application/json\r\nContent-Length: ten\r\n\r\n{\"a\":1}\r\n",
                   VciErrorCode::BadContentLength, 400);
    expectRecovery("PUT /x VCI/1.0\r\nContent-Length: 2\r\nContent-Length: 3\r\n\r\n{}\r\n", VciErrorCode::BadContentLength, 400);
    expectRecovery("PUT /x VCI/1.0\r\nContent-Length: -1\r\n\r\n", VciErrorCode::BadContentLength, 400);
}

void TstVciBadInput::lineTooLong()
{
    VciLimits limits;
    limits.maxLineLength = 64;
    expectRecovery("GET /" + std::string(200, 'a') + " VCI/1.0\r\n\r\n", VciErrorCode::LineTooLong, 400, limits);
    expectRecovery("GET /x VCI/1.0\r\nX-Long: " + std::string(500, 'b') + "\r\n\r\n", VciErrorCode::LineTooLong, 400, limits);
    // Exactly at the limit (line ending included) is fine.
    const std::string line = "GET /" + std::string(64 - 15, 'c') + " VCI/1.0\r\n";
    QCOMPARE(line.size(), size_t(64));
    const auto r = parseAll(line + "\r\n", limits);
    QVERIFY(std::holds_alternative<VciMessage>(r.at(0)));
    const auto over = parseAll("GET /d" + line.substr(5) + "\r\n", limits);
    QVERIFY(std::holds_alternative<VciParseError>(over.at(0)));
}

void TstVciBadInput::tooManyHeaders()
{
    std::string m = "GET /x VCI/1.0\r\n";
    for (int i = 0; i < 101; ++i)
        m += "X-" + std::to_string(i) + ": v\r\n";
    expectRecovery(m + "\r\n", VciErrorCode::TooManyHeaders, 400);
}

void TstVciBadInput::bodyTooLarge()
{
    VciLimits limits;
    limits.maxBodySize = 1024;
    expectRecovery("PUT /x VCI/1.0\r\nContent-Type: application/json\r\nContent-Length: 5000\r\n\r\n[" + std::string(300, '1') + "\r\n",
                   VciErrorCode::BodyTooLarge, 400, limits);
    std::string big = "[";
    for (int i = 0; i < 600; ++i)
        big += "1,";
    expectRecovery("PUT /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n" + big + "\r\n", VciErrorCode::BodyTooLarge, 400, limits);
    expectRecovery("PUT /x VCI/1.0\r\nContent-Length: 99999999999999999999\r\n\r\n", VciErrorCode::BadContentLength, 400, limits);
}

void TstVciBadInput::missingEmptyLine()
{
    expectRecovery("GET /x VCI/1.0\r\nA: b\r\n", VciErrorCode::MissingEmptyLine, 400);
}

void TstVciBadInput::brokenResponseAndNotifyGetNoReply()
{
    expectRecovery("VCI/1.0 200 OK\r\nContent-Type: application/json\r\n\r\n{oops}\r\n", VciErrorCode::BadJson, 0);
    expectRecovery("NOTIFY /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n[,]\r\n", VciErrorCode::BadJson, 0);
}

void TstVciBadInput::garbageKeepsMemoryBounded()
{
    VciLimits limits;
    limits.maxLineLength = 1024;
    VciParser parser(limits);
    std::string chunk(4096, 'z');
    size_t errors = 0;
    for (int i = 0; i < 1000; ++i) { // 4 MB without a line end
        parser.feed(chunk);
        while (auto r = parser.next())
            errors += std::holds_alternative<VciParseError>(*r);
        QVERIFY(parser.buffered() <= limits.maxLineLength);
    }
    parser.feed("\r\n\r\n" + kNext);
    std::vector<VciParser::Result> rest;
    while (auto r = parser.next())
        rest.push_back(std::move(*r));
    QCOMPARE(errors + rest.size(), size_t(2)); // the one over-long "start line", then /next
    QCOMPARE(std::get<VciMessage>(rest.back()).uri, std::string("/next"));

    // A JSON body without length that never ends stays within the body limit too.
    VciLimits small;
    small.maxBodySize = 64 * 1024;
    VciParser p2(small);
    p2.feed("PUT /x VCI/1.0\r\nContent-Type: application/json\r\n\r\n[");
    size_t errs = 0;
    for (int i = 0; i < 100; ++i) {
        p2.feed(std::string(4096, ' '));
        while (auto r = p2.next())
            errs += std::holds_alternative<VciParseError>(*r);
        QVERIFY(p2.buffered() <= 4096 + small.maxLineLength);
    }
    QCOMPARE(errs, size_t(1));
    QVERIFY(p2.bytesDiscarded() > 0);
}

void TstVciBadInput::randomNoiseNeverCrashes()
{
    std::mt19937 rng(12345);
    const std::string alphabet = "GETPUTNOTIFYSUBSCRIBE VCI/1.0 200 OK\r\n:{}[]\",0123456789-.eE truefalsenull\\uContent-Length: application/json";
    for (int round = 0; round < 200; ++round) {
        std::string noise;
        const size_t n = rng() % 400;
        for (size_t i = 0; i < n; ++i)
            noise += rng() % 8 ? alphabet[rng() % alphabet.size()] : char(rng() % 256);
        std::vector<size_t> cuts;
        for (size_t c = 1 + rng() % 17; c < noise.size(); c += 1 + rng() % 17)
            cuts.push_back(c);
        // Whatever the noise, the same results come out however it is chunked, and a clean message
        // after an empty line and a fresh start line is still read.
        const std::string stream = noise + "\r\n\r\n" + kNext + kNext;
        const auto whole = parseAll(stream);
        QCOMPARE(describe(parseChunked(stream, cuts)), describe(whole));
        QVERIFY(!whole.empty());
        QVERIFY2(std::holds_alternative<VciMessage>(whole.back()), describe(whole).c_str());
    }
}

QTEST_GUILESS_MAIN(TstVciBadInput)
#include "tst_vcibadinput.moc"
