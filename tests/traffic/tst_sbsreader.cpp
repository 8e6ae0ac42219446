// The SBS-1 (BaseStation) codec against hand-written lines in the published format: 22 fields,
// MSG transmission types 1 to 8, absent values empty. Malformed lines are named and skipped.
#include "SbsReader.h"
#include "SbsWriter.h"

#include <QTest>

using namespace sortie::traffic::sbs;

namespace {

std::vector<SbsReader::Result> readAll(const std::string &bytes, size_t chunk = 0, SbsReader *out = nullptr)
{
    SbsReader local;
    SbsReader &reader = out ? *out : local;
    if (chunk == 0) {
        reader.push(bytes);
    } else {
        for (size_t i = 0; i < bytes.size(); i += chunk)
            reader.push(std::string_view(bytes).substr(i, chunk));
    }
    std::vector<SbsReader::Result> results;
    while (auto r = reader.next())
        results.push_back(std::move(*r));
    return results;
}

const SbsMessage &message(const SbsReader::Result &r)
{
    return std::get<SbsMessage>(r);
}

const SbsError &error(const SbsReader::Result &r)
{
    return std::get<SbsError>(r);
}

const std::string kTime = "2026/11/26,18:44:00.123,2026/11/26,18:44:00.125";

std::string line(const std::string &head, const std::string &tail)
{
    return head + "," + kTime + "," + tail + "\r\n";
}

} // namespace

class TestSbsReader : public QObject
{
    Q_OBJECT

private slots:
    void identificationPositionAndVelocity()
    {
        const std::string feed = line("MSG,1,1,1,4CA2D6,1", "RYR2PN  ,,,,,,,,,,,") // call sign, padded
                                 + line("MSG,3,1,1,4CA2D6,1", ",37000,,,56.97650,24.07600,,,0,0,0,0")
                                 + line("MSG,4,1,1,4CA2D6,1", ",,452,271,,,-64,,,,,");
        const auto results = readAll(feed);
        QCOMPARE(results.size(), size_t(3));
        const SbsMessage &id = message(results[0]);
        QCOMPARE(id.line, uint64_t(1));
        QCOMPARE(id.transmission, 1);
        QCOMPARE(id.address, 0x4CA2D6u);
        QCOMPARE(id.callsign.value(), std::string("RYR2PN"));
        QVERIFY(!id.altitudeFt && !id.latitude && !id.groundSpeedKt && !id.onGround); // absent, never 0

        const SbsMessage &position = message(results[1]);
        QCOMPARE(position.transmission, 3);
        QCOMPARE(position.altitudeFt.value(), 37000.0);
        QCOMPARE(position.latitude.value(), 56.9765);
        QCOMPARE(position.longitude.value(), 24.076);
        QCOMPARE(position.onGround.value(), false);
        QVERIFY(!position.callsign && !position.trackDeg && !position.verticalRateFpm);

        const SbsMessage &velocity = message(results[2]);
        QCOMPARE(velocity.transmission, 4);
        QCOMPARE(velocity.groundSpeedKt.value(), 452.0);
        QCOMPARE(velocity.trackDeg.value(), 271.0);
        QCOMPARE(velocity.verticalRateFpm.value(), -64.0);
        QVERIFY(!velocity.latitude && !velocity.alert && !velocity.onGround);
    }

    void surveillanceSquawkAndFlags()
    {
        const auto results = readAll(line("MSG,6,1,1,502C11,1", ",2300,,,,,,7700,-1,-1,0,0") + line("MSG,5,1,1,502C11,1", ",2325,,,,,,,0,,0,-1")
                                     + line("MSG,8,1,1,502C11,1", ",,,,,,,,,,,0") + line("MSG,2,1,1,~1A2B3C,1", ",0,12,90,56.9,24.1,,,,,,-1"));
        QCOMPARE(results.size(), size_t(4));
        const SbsMessage &six = message(results[0]);
        QCOMPARE(six.squawk.value(), std::string("7700"));
        QCOMPARE(six.alert.value(), true);
        QCOMPARE(six.emergency.value(), true);
        QCOMPARE(six.ident.value(), false);
        QCOMPARE(six.altitudeFt.value(), 2300.0);
        const SbsMessage &five = message(results[1]);
        QVERIFY(!five.emergency); // empty: absent
        QCOMPARE(five.onGround.value(), true);
        QCOMPARE(message(results[2]).onGround.value(), false);
        const SbsMessage &surface = message(results[3]);
        QVERIFY(surface.nonIcaoAddress);
        QCOMPARE(surface.address, 0x1A2B3Cu);
        QCOMPARE(surface.groundSpeedKt.value(), 12.0);
    }

    // The other BaseStation kinds and empty lines are skipped and counted, not errors.
    void otherKindsAreSkipped()
    {
        SbsReader reader;
        const auto results = readAll("STA,,5,179,400AE7,10103," + kTime + ",RM\r\n\r\nAIR,,333,5,4CA2D6,10101," + kTime + "\n"
                                         + line("MSG,8,1,1,4CA2D6,1", ",,,,,,,,,,,0"),
                                     0, &reader);
        QCOMPARE(results.size(), size_t(1));
        QCOMPARE(message(results[0]).line, uint64_t(4));
        QCOMPARE(reader.skippedLines(), uint64_t(3));
        QCOMPARE(reader.linesSeen(), uint64_t(4));
    }

    void malformedLinesAreNamedAndSkipped_data()
    {
        QTest::addColumn<QByteArray>("bad");
        QTest::addColumn<QString>("reason");
        const auto row = [](const char *name, const std::string &bad, const char *reason) {
            QTest::newRow(name) << QByteArray::fromStdString(bad) << QString::fromLatin1(reason);
        };
        row("latitude out of range", line("MSG,3,1,1,4CA2D6,1", ",37000,,,91.50000,24.07600,,,0,0,0,0"), "field 15 (latitude): 91.50000 is out of -90..90");
        row("longitude not a number", line("MSG,3,1,1,4CA2D6,1", ",37000,,,56.9,east,,,0,0,0,0"), "field 16 (longitude): 'east' is not a number");
        row("transmission type 9", line("MSG,9,1,1,4CA2D6,1", ",,,,,,,,,,,"), "field 2 (transmission type): '9' is not 1 to 8");
        row("address not hex", line("MSG,3,1,1,4CZ2D6,1", ",37000,,,,,,,,,,"), "field 5 (address): '4CZ2D6' is not a 24-bit hexadecimal address");
        row("address too long", line("MSG,3,1,1,4CA2D60,1", ",37000,,,,,,,,,,"), "field 5 (address): '4CA2D60' is not a 24-bit hexadecimal address");
        row("address empty", line("MSG,3,1,1,,1", ",37000,,,,,,,,,,"), "field 5 (address): '' is not a 24-bit hexadecimal address");
        row("21 fields", line("MSG,3,1,1,4CA2D6,1", ",37000,,,,,,,,,"), "21 fields where an SBS-1 line has 22");
        row("23 fields", line("MSG,3,1,1,4CA2D6,1", ",37000,,,,,,,,,,,"), "23 fields where an SBS-1 line has 22");
        row("unknown type", line("MSX,3,1,1,4CA2D6,1", ",,,,,,,,,,,"), "field 1 (message type): 'MSX' is not MSG, SEL, ID, AIR, STA or CLK");
        row("latitude alone", line("MSG,3,1,1,4CA2D6,1", ",37000,,,56.9,,,,0,0,0,0"), "a latitude without a longitude");
        row("bad flag", line("MSG,3,1,1,4CA2D6,1", ",37000,,,,,,,2,0,0,0"), "field 19 (alert): '2' is not -1, 1 or 0");
        row("squawk not octal", line("MSG,6,1,1,4CA2D6,1", ",37000,,,,,,7800,0,0,0,0"), "field 18 (squawk): '7800' is not four octal digits");
        row("call sign too long", line("MSG,1,1,1,4CA2D6,1", "ABCDEFGHI,,,,,,,,,,,"), "field 11 (call sign): 'ABCDEFGHI' is longer than 8 characters");
        row("call sign with a dollar", line("MSG,1,1,1,4CA2D6,1", "AB$12,,,,,,,,,,,"), "field 11 (call sign): 'AB$12' holds a character a call sign cannot");
        row("altitude infinite", line("MSG,5,1,1,4CA2D6,1", ",inf,,,,,,,,,,"), "field 12 (altitude): 'inf' is not a number");
        row("altitude hex float", line("MSG,5,1,1,4CA2D6,1", ",0x10,,,,,,,,,,"), "field 12 (altitude): '0x10' is not a number");
        row("speed negative", line("MSG,4,1,1,4CA2D6,1", ",,-5,90,,,0,,,,,"), "field 13 (ground speed): -5 is out of 0..4000");
        row("track above 360", line("MSG,4,1,1,4CA2D6,1", ",,100,361,,,0,,,,,"), "field 14 (track): 361 is out of 0..360");
    }

    // The bad line is dropped with its number and reason; the good lines on either side are read.
    void malformedLinesAreNamedAndSkipped()
    {
        QFETCH(QByteArray, bad);
        QFETCH(QString, reason);
        const std::string good = line("MSG,8,1,1,4CA2D6,1", ",,,,,,,,,,,0");
        const auto results = readAll(good + bad.toStdString() + good);
        QCOMPARE(results.size(), size_t(3));
        QCOMPARE(message(results[0]).line, uint64_t(1));
        QCOMPARE(error(results[1]).line, uint64_t(2));
        QCOMPARE(QString::fromStdString(error(results[1]).reason), reason);
        QCOMPARE(message(results[2]).line, uint64_t(3));
    }

    // A line past the limit is dropped when it passes it; reading starts again after its newline.
    void tooLongLineResynchronises()
    {
        SbsReader reader(100);
        const std::string good = line("MSG,8,1,1,4CA2D6,1", ",,,,,,,,,,,0");
        reader.push(good + std::string(150, 'x'));
        QCOMPARE(reader.buffered(), size_t(0)); // the long line is not kept
        reader.push(std::string(5000, 'y'));
        QCOMPARE(reader.buffered(), size_t(0));
        reader.push("\n" + good);
        std::vector<SbsReader::Result> results;
        while (auto r = reader.next())
            results.push_back(*r);
        QCOMPARE(results.size(), size_t(3));
        QCOMPARE(error(results[1]).line, uint64_t(2));
        QCOMPARE(error(results[1]).reason, std::string("longer than 100 bytes: skipped to the next newline"));
        QCOMPARE(message(results[2]).line, uint64_t(3));
    }

    // Bytes arriving one at a time read as the whole stream does.
    void chunkingDoesNotMatter()
    {
        const std::string feed = line("MSG,1,1,1,4CA2D6,1", "RYR2PN,,,,,,,,,,,") + line("MSG,3,1,1,4CA2D6,1", ",37000,,,91.0,24.0,,,0,0,0,0")
                                 + "garbage\n" + line("MSG,4,1,1,4CA2D6,1", ",,452,271,,,-64,,,,,");
        const auto whole = readAll(feed);
        for (size_t chunk : {1, 2, 7, 64}) {
            const auto pieces = readAll(feed, chunk);
            QCOMPARE(pieces.size(), whole.size());
            for (size_t i = 0; i < whole.size(); ++i)
                QVERIFY(pieces[i] == whole[i]);
        }
    }

    // What the simulator writes reads back the same (rounded as the format writes it).
    void writerRoundTrip()
    {
        SbsMessage m;
        m.transmission = 3;
        m.address = 0x502C11;
        m.altitudeFt = 820;
        m.latitude = 56.97650;
        m.longitude = 24.07600;
        m.alert = m.emergency = m.ident = m.onGround = false;
        const std::string text = writeSbsLine(m, 1795718640123); // 2026-11-26 18:44:00.123 UTC
        QCOMPARE(text, std::string("MSG,3,1,1,502C11,1,2026/11/26,18:44:00.123,2026/11/26,18:44:00.123,,820,,,56.97650,24.07600,,,0,0,0,0\r\n"));
        const auto back = readAll(text);
        QCOMPARE(back.size(), size_t(1));
        SbsMessage expected = m;
        expected.line = 1;
        QVERIFY(message(back[0]) == expected);
    }
};

QTEST_APPLESS_MAIN(TestSbsReader)
#include "tst_sbsreader.moc"
