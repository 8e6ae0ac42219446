// The incremental JSON reader against nlohmann::json::parse: same values, same rejections, any chunking.
#include "VciJsonReader.h"

#include <QtTest>

using nlohmann::json;
using sortie::vci::VciJsonReader;

namespace {

struct Outcome
{
    VciJsonReader::Status status;
    json value;
    size_t consumed;
    std::string error;
};

// Feeds `text` in chunks of `chunk` bytes; `bounded` says the input ends there (Content-Length).
Outcome read(const std::string &text, size_t chunk, bool bounded)
{
    VciJsonReader r;
    size_t used = 0;
    while (used < text.size() && r.status() == VciJsonReader::Status::NeedMore) {
        const size_t n = std::min(chunk, text.size() - used);
        used += r.feed(text.data() + used, n);
        if (r.status() == VciJsonReader::Status::NeedMore && used < text.size() && n == 0)
            break;
    }
    if (bounded && r.status() == VciJsonReader::Status::NeedMore)
        r.finish();
    return {r.status(), r.value(), used, r.error()};
}

} // namespace

class TstVciJsonReader : public QObject
{
    Q_OBJECT
private slots:
    void matchesNlohmann_data();
    void matchesNlohmann();
    void topLevelNumberEndsAtOneWhitespace();
    void valueEndsAtItsLastByte();
    void rejectsWhatJsonRejects_data();
    void rejectsWhatJsonRejects();
    void limits();
    void errorNamesThePlace();
};

void TstVciJsonReader::matchesNlohmann_data()
{
    QTest::addColumn<QByteArray>("text");
    const char *texts[] = {
        "{}", "[]", "\"\"", "true", "false", "null", "0 ", "-0 ", "42 ", "-17 ", "3.25 ", "-1.5e-3 ", "6.02E+23 ",
        "18446744073709551615 ", "-9223372036854775808 ", "1e400000000000000000000000000000000000000000 ",
        "{\"latitude\":0.99442,\"longitude\":0.42015,\"altitudeAmsl\":512.5,\"time\":1700000000000}",
        "[[1,[2,[3,[]]]],[],{}]",
        "\"braces {inside} and [brackets] \\\"quoted\\\" and \\\\ backslash\"",
        "{\"a{\":\"}b\",\"c\\\"\":[\"]\",\"[\"]}",
        "\"\\u00e9\\u20ac\\ud83d\\ude00 \\/ \\b\\f\\n\\r\\t\"",
        "\"caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80\"",
        "  \r\n\t {\"spaced\" : [ 1 , 2 ] , \"x\" : null }",
        "{\"dup\":1,\"dup\":2}",
        "[1.0, -0.0, 1E2, 0.5e-400]",
    };
    for (const char *t : texts)
        QTest::newRow(t) << QByteArray(t);
}

void TstVciJsonReader::matchesNlohmann()
{
    QFETCH(QByteArray, text);
    const std::string s = text.toStdString();
    json expected;
    try {
        expected = json::parse(s);
    } catch (const json::exception &) {
        // nlohmann refuses numbers it cannot hold; we require those to be tiny (read as 0) only.
        QVERIFY(s.find("e4") != std::string::npos);
        const Outcome o = read(s, s.size(), true);
        QCOMPARE(o.status, VciJsonReader::Status::Error);
        QVERIFY2(o.error.find("out of range") != std::string::npos, o.error.c_str());
        return;
    }
    for (size_t chunk : {size_t(1), size_t(2), size_t(3), size_t(7), s.size()}) {
        const Outcome o = read(s, chunk, true);
        QVERIFY2(o.status == VciJsonReader::Status::Done, o.error.c_str());
        QCOMPARE(o.value.dump(), expected.dump());
        QCOMPARE(o.value.type(), expected.type());
    }
}

void TstVciJsonReader::topLevelNumberEndsAtOneWhitespace()
{
    // Unbounded (JSON framing): the number needs its whitespace, which belongs to the body.
    Outcome o = read("42", 64, false);
    QCOMPARE(o.status, VciJsonReader::Status::NeedMore);
    o = read("42\r\nGET", 64, false);
    QCOMPARE(o.status, VciJsonReader::Status::Done);
    QCOMPARE(o.value, json(42));
    QCOMPARE(o.consumed, size_t(3)); // "42\r": the \n is the next message's
    o = read("-3.5e2 {", 1, false);
    QCOMPARE(o.status, VciJsonReader::Status::Done);
    QCOMPARE(o.value.get<double>(), -350.0);
    QCOMPARE(o.consumed, size_t(7));
    // Bounded (Content-Length): the end of the input ends it.
    o = read("42", 64, true);
    QCOMPARE(o.status, VciJsonReader::Status::Done);
    QCOMPARE(o.value, json(42));
    // Anything but whitespace after a top-level number is an error.
    o = read("42}", 64, false);
    QCOMPARE(o.status, VciJsonReader::Status::Error);
}

void TstVciJsonReader::valueEndsAtItsLastByte()
{
    const struct { const char *text; size_t end; } cases[] = {
        {"{\"a\":[1,2]}VCI/1.0", 11}, {"[\"]\"]X", 5}, {"\"{\\\"}\"Z", 6}, {"trueGET", 4}, {"nullnull", 4}, {"false ", 5},
    };
    for (const auto &c : cases) {
        for (size_t chunk : {size_t(1), size_t(64)}) {
            const Outcome o = read(c.text, chunk, false);
            QCOMPARE(o.status, VciJsonReader::Status::Done);
            QCOMPARE(o.consumed, c.end);
        }
    }
}

void TstVciJsonReader::rejectsWhatJsonRejects_data()
{
    QTest::addColumn<QByteArray>("text");
    const char *texts[] = {
        "{,}", "[1,]", "{\"a\":1,}", "{\"a\" 1}", "{1:2}", "[1 2]", "01 ", "1. ", ".5 ", "-x", "1e ", "+1 ",
        "tru ", "nul!", "\"unterminated\x01\"", "\"bad \\x escape\"", "\"\\u12G4\"", "\"\\ud800\"", "\"\\udc00\"",
        "\"\\ud800\\u0041\"", "\"\xc3\x28\"", "\"\xe0\x80\xaf\"", "\"\xed\xa0\x80\"", "\"\xf5\x80\x80\x80\"", "\"\xc0\xaf\"",
        "]", "}", "{\"a\":1]", "[1}", "'single'", "NaN ", "Infinity ",
    };
    for (const char *t : texts)
        QTest::newRow(t) << QByteArray(t);
}

void TstVciJsonReader::rejectsWhatJsonRejects()
{
    QFETCH(QByteArray, text);
    const std::string s = text.toStdString();
    QVERIFY_THROWS_EXCEPTION(json::exception, json::parse(s));
    for (size_t chunk : {size_t(1), s.size()}) {
        const Outcome o = read(s, chunk, true);
        QCOMPARE(o.status, VciJsonReader::Status::Error);
        QVERIFY(!o.error.empty());
    }
}

void TstVciJsonReader::limits()
{
    std::string deep(300, '[');
    VciJsonReader r(256);
    r.feed(deep.data(), deep.size());
    QCOMPARE(r.status(), VciJsonReader::Status::Error);
    QVERIFY2(r.error().find("deeper than 256") != std::string::npos, r.error().c_str());
    QCOMPARE(r.consumed(), uint64_t(256)); // stopped at the opening bracket that went too deep

    VciJsonReader small(256, 100);
    const std::string big = "[" + std::string(200, '1');
    small.feed(big.data(), big.size());
    QCOMPARE(small.status(), VciJsonReader::Status::Error);
    QVERIFY(small.consumed() <= 100);

    VciJsonReader numbers(256, 1 << 20, 16);
    const std::string longNumber(40, '7');
    numbers.feed(longNumber.data(), longNumber.size());
    QCOMPARE(numbers.status(), VciJsonReader::Status::Error);

    // reset() makes the reader ready for the next body.
    r.reset();
    r.feed("[1]", 3);
    QCOMPARE(r.status(), VciJsonReader::Status::Done);
    QCOMPARE(r.value(), json::array({1}));
}

void TstVciJsonReader::errorNamesThePlace()
{
    const Outcome o = read("{\"a\": [1, 2,, 3]}", 4, true);
    QCOMPARE(o.status, VciJsonReader::Status::Error);
    QVERIFY2(o.error.find("body byte 12") != std::string::npos, o.error.c_str());
    QVERIFY2(o.error.find("expected a JSON value, found ','") != std::string::npos, o.error.c_str());
    QCOMPARE(o.consumed, size_t(12));
}

QTEST_GUILESS_MAIN(TstVciJsonReader)
#include "tst_vcijsonreader.moc"
