// TelemetryBlockCodec on byte strings: every value comes back as its quantum, missing stays
// missing, typical telemetry takes under 4 bytes a value, and a damaged block is refused, never
// misread.
#include "TelemetryBlockCodec.h"

#include <QRandomGenerator>
#include <QTest>

#include <cmath>

using namespace sortie;
using flightlog::BlockFields;
using flightlog::FieldSamples;
using flightlog::TelemetryBlockCodec;
using vehicle::TelemetryField;

namespace {
// One second of 10 Hz telemetry of a vehicle flying north-east at 8 m/s, with jittery times.
BlockFields typicalSecond(int64_t t0, QRandomGenerator &rng)
{
    BlockFields fields;
    for (size_t f = 0; f < vehicle::kTelemetryFieldCount; ++f)
        fields.push_back({TelemetryField(f), {}});
    for (int i = 0; i < 10; ++i) {
        const int64_t t = t0 + i * 100 + int64_t(rng.bounded(3));
        const double s = double(t - 1'700'000'000'000) / 1000.0;
        const double v[] = {0.9943 + s * 1.25e-7, 0.4207 + s * 1.2e-7, 60 + 0.01 * s, 50 + 0.01 * s,
                            0.02 * std::sin(s), -0.05 + 0.01 * std::cos(s), 0.785 + 0.001 * std::sin(s / 3), 0.78,
                            8 + 0.1 * std::sin(s), 8.5, 0.01, 16.2 - s * 1e-4, 12.5, 0.8 - s * 1e-5, 3, 14, 0.8,
                            0.9943, 0.4207, 10, 1, 4, 1, 3, 2, 6, 0, 1};
        static_assert(sizeof(v) / sizeof(v[0]) == vehicle::kTelemetryFieldCount, "one value per telemetry field");
        for (size_t f = 0; f < vehicle::kTelemetryFieldCount; ++f) // angles as HCI sends them; the store speaks degrees
            fields[f].samples.push_back({t, vehicle::isAngle(TelemetryField(f)) ? vehicle::degreesFromRadians(v[f]) : v[f]});
    }
    return fields;
}
} // namespace

class TestBlockCodec : public QObject
{
    Q_OBJECT

private slots:
    void roundTripIsTheQuantisedValue()
    {
        QRandomGenerator rng(7);
        BlockFields in = typicalSecond(1'700'000'000'000, rng);
        // Irregular times, a backwards step, a field with times of its own, a value far from the others.
        in[2].samples[4].time = in[0].samples[0].time - 30; // earlier than anything: the block starts there
        in[5].samples.pop_back();
        in[8].samples[5].value = 1234.5678;
        const std::string block = TelemetryBlockCodec::encode(in);
        std::string error;
        const auto out = TelemetryBlockCodec::decode(block, &error);
        QVERIFY2(out, error.c_str());
        QCOMPARE(out->size(), in.size());
        for (size_t f = 0; f < in.size(); ++f) {
            QCOMPARE((*out)[f].field, in[f].field);
            QCOMPARE((*out)[f].samples.size(), in[f].samples.size());
            for (size_t i = 0; i < in[f].samples.size(); ++i) {
                QCOMPARE((*out)[f].samples[i].time, in[f].samples[i].time);
                const double expected = flightlog::quantize(in[f].field, in[f].samples[i].value);
                QCOMPARE((*out)[f].samples[i].value, expected);
                QVERIFY(std::fabs(expected - in[f].samples[i].value) <= flightlog::fieldStep(in[f].field) / 2 * 1.0000001);
            }
        }
        const auto summary = TelemetryBlockCodec::summarize(block);
        QVERIFY(summary);
        QCOMPARE(summary->total, uint32_t(10 * vehicle::kTelemetryFieldCount - 1));
        QCOMPARE(summary->t0, in[2].samples[4].time);
    }

    void missingStaysMissing()
    {
        BlockFields in{{TelemetryField::AltitudeAgl, {{1000, 5.0}, {1100, std::nan("")}, {1200, 7.0}, {1300, INFINITY}}},
                       {TelemetryField::AltitudeAmsl, {{1000, std::nan("")}, {1100, std::nan("")}, {1200, std::nan("")}, {1300, std::nan("")}}}};
        const auto out = TelemetryBlockCodec::decode(TelemetryBlockCodec::encode(in));
        QVERIFY(out);
        for (const auto &sample : (*out)[1].samples) // a field with nothing but missing values
            QVERIFY(std::isnan(sample.value));
        QCOMPARE((*out)[1].samples[3].time, 1300);
        const auto &s = out->front().samples;
        QCOMPARE(s[0].value, 5.0);
        QVERIFY(std::isnan(s[1].value));
        QCOMPARE(s[2].value, 7.0);
        QVERIFY(std::isnan(s[3].value));
    }

    void onlyOneField()
    {
        QRandomGenerator rng(1);
        const std::string block = TelemetryBlockCodec::encode(typicalSecond(1'700'000'000'000, rng));
        const auto out = TelemetryBlockCodec::decode(block, nullptr, TelemetryField::Heading);
        QVERIFY(out);
        QCOMPARE(out->size(), size_t(1));
        QCOMPARE(out->front().field, TelemetryField::Heading);
    }

    void logsFromBeforeDegreesReadTheSame()
    {
        // A block written when the store still spoke radians (the codec of 3a8ec23, fed 56.95° and
        // 24.10°, 100 m, a heading of 90° then 270°, a roll of -0.1 then 0.2 rad, all in radians):
        // its integers are quanta of 1e-9 rad and 1e-5 rad, and they read back as those angles in
        // degrees. It is a version 1 block (before constant fields): encoding the same angles in
        // degrees now writes a version 2 block with the very same integers.
        using F = TelemetryField;
        const std::string golden = QByteArray::fromHex(
            "0180a0abfef962c801050002000a00c801a2cff5b307a21b01020407bcdf919103c43602020405c09a0ce80706020406b09613deac26"
            "040204069f9c01e0d403dc3a0606").toStdString();
        std::string error;
        const auto out = TelemetryBlockCodec::decode(golden, &error);
        QVERIFY2(out, error.c_str());
        auto values = [&](F field) {
            std::vector<double> v;
            for (const FieldSamples &f : *out)
                if (f.field == field)
                    for (const auto &s : f.samples)
                        v.push_back(s.value);
            return v;
        };
        const double position = flightlog::fieldStep(F::Latitude), attitude = flightlog::fieldStep(F::Heading);
        QVERIFY(std::fabs(position - 1e-9 * 180 / M_PI) < 1e-20);
        QVERIFY(std::fabs(attitude - 1e-5 * 180 / M_PI) < 1e-16);
        const auto lat = values(F::Latitude), lon = values(F::Longitude), heading = values(F::Heading), roll = values(F::Roll);
        QCOMPARE(lat.size(), size_t(2));
        QVERIFY(std::fabs(lat[0] - 56.95) <= position && std::fabs(lat[1] - 56.9501) <= position);
        QVERIFY(std::fabs(lon[0] - 24.10) <= position && std::fabs(lon[1] - 24.1002) <= position);
        QCOMPARE(values(F::AltitudeAmsl), (std::vector<double>{100.0, 100.5}));
        QVERIFY(std::fabs(heading[0] - 90) <= attitude && std::fabs(heading[1] - 270) <= attitude);
        QVERIFY(std::fabs(roll[0] + 0.1 * 180 / M_PI) <= attitude && std::fabs(roll[1] - 0.2 * 180 / M_PI) <= attitude);
        const std::string again = TelemetryBlockCodec::encode(*out);
        QCOMPARE(again.front(), '\x02');
        QCOMPARE(again.substr(1, again.size() - 5), golden.substr(1, golden.size() - 5)); // no field is constant here
        const BlockFields degrees = {
            {F::Latitude, {{1'700'000'000'000, 56.95}, {1'700'000'000'100, 56.9501}}},
            {F::Longitude, {{1'700'000'000'000, 24.10}, {1'700'000'000'100, 24.1002}}},
            {F::AltitudeAmsl, {{1'700'000'000'000, 100.0}, {1'700'000'000'100, 100.5}}},
            {F::Heading, {{1'700'000'000'000, 90.0}, {1'700'000'000'100, 270.0}}},
            {F::Roll, {{1'700'000'000'000, -0.1 * 180 / M_PI}, {1'700'000'000'100, 0.2 * 180 / M_PI}}},
        };
        QCOMPARE(TelemetryBlockCodec::encode(degrees), again);
    }

    // A field whose every value is the same (a fix type, a mode, a parked vehicle) is written once.
    void aConstantFieldIsWrittenOnce()
    {
        using F = TelemetryField;
        BlockFields fields{{F::Latitude, {}}, {F::GpsFix, {}}, {F::AltitudeAmsl, {}}};
        for (int i = 0; i < 10; ++i) {
            const int64_t t = 1'700'000'000'000 + i * 100 + i % 3;
            fields[0].samples.push_back({t, 56.95 + i * 1e-5});
            fields[1].samples.push_back({t, 3});
            fields[2].samples.push_back({t, 120.5}); // hovering
        }
        const std::string block = TelemetryBlockCodec::encode(fields);
        std::string error;
        const auto out = TelemetryBlockCodec::decode(block, &error);
        QVERIFY2(out, error.c_str());
        QCOMPARE(out->size(), size_t(3));
        for (size_t f = 0; f < 3; ++f)
            for (size_t i = 0; i < 10; ++i) {
                QCOMPARE((*out)[f].samples[i].time, fields[f].samples[i].time);
                QCOMPARE((*out)[f].samples[i].value, flightlog::quantize(fields[f].field, fields[f].samples[i].value));
            }
        QCOMPARE(TelemetryBlockCodec::summarize(block)->total, 30u);
        // Each constant field: id, count, flags, length and one value (times shared): 5 bytes, not 14.
        BlockFields withoutConstants{fields[0]};
        QCOMPARE(block.size() - TelemetryBlockCodec::encode(withoutConstants).size(), size_t(4 + 1 + 4 + 2 + 1));
        // A constant field may not claim more samples than a block can hold.
        std::string hostile = block;
        // The GpsFix field follows the latitude's (same header sizes: same times, one-byte field count).
        const size_t id = TelemetryBlockCodec::encode(withoutConstants).size() - 4, count = id + 1;
        QCOMPARE(uchar(hostile[id]), uchar(F::GpsFix));
        QCOMPARE(uchar(hostile[count]), uchar(10));
        hostile.replace(count, 1, std::string("\x81\x80\x02", 3)); // 32,769 samples
        hostile.resize(hostile.size() - 4);
        const uint32_t crc = flightlog::crc32(hostile);
        hostile.append(reinterpret_cast<const char *>(&crc), 4);
        QVERIFY(!TelemetryBlockCodec::decode(hostile, &error));
        QCOMPARE(error, std::string("bad field header"));
    }

    void typicalTelemetryTakesUnderFourBytesAValue()
    {
        QRandomGenerator rng(3);
        size_t bytes = 0, values = 0;
        for (int second = 0; second < 60; ++second) {
            const BlockFields in = typicalSecond(1'700'000'000'000 + second * 1000, rng);
            bytes += TelemetryBlockCodec::encode(in).size();
            values += 10 * vehicle::kTelemetryFieldCount;
        }
        const double perValue = double(bytes) / double(values);
        qInfo("typical 10 Hz telemetry: %.2f bytes per value", perValue);
        QVERIFY2(perValue < 4.0, qPrintable(QString::number(perValue)));
    }

    void damageIsRefused()
    {
        QRandomGenerator rng(5);
        const std::string block = TelemetryBlockCodec::encode(typicalSecond(1'700'000'000'000, rng));
        std::string error;
        for (size_t at : {size_t(0), size_t(3), block.size() / 2, block.size() - 1}) {
            std::string bad = block;
            bad[at] = char(bad[at] ^ 0x40);
            QVERIFY(!TelemetryBlockCodec::decode(bad, &error));
            QVERIFY(!error.empty());
        }
        QVERIFY(!TelemetryBlockCodec::decode(block.substr(0, block.size() / 2), &error));
        QCOMPARE(error, std::string("checksum mismatch"));
        QVERIFY(!TelemetryBlockCodec::summarize(std::string("\x01", 1), &error));
        // Random bytes with a valid checksum still never read out of bounds (the fuzz target goes further).
        for (int i = 0; i < 2000; ++i) {
            std::string junk(size_t(rng.bounded(1, 64)), '\0');
            for (char &c : junk)
                c = char(rng.bounded(256));
            const uint32_t crc = flightlog::crc32(junk);
            junk.append(reinterpret_cast<const char *>(&crc), 4);
            TelemetryBlockCodec::decode(junk);
            TelemetryBlockCodec::summarize(junk);
        }
    }

    // Found by fuzz_telemetry_block: a block naming one field twice was decoded as two runs of it
    // (and summarized as one). Both readers refuse it now.
    void aFieldTwiceIsRefused()
    {
        BlockFields fields{{TelemetryField::Latitude, {{1000, 56.9}, {1100, 56.91}}},
                           {TelemetryField::Longitude, {{1000, 24.1}, {1100, 24.11}}}};
        std::string block = TelemetryBlockCodec::encode(fields);
        QVERIFY(TelemetryBlockCodec::decode(block));
        // Header: version, t0, span, field count (varints); then the first field: its id, count,
        // flags, payload length and payload; the second field's id follows.
        const auto varintEnd = [&block](size_t at) { while (uchar(block[at]) & 0x80) ++at; return at + 1; };
        size_t at = varintEnd(varintEnd(varintEnd(1)));
        QCOMPARE(uchar(block[at]), uchar(TelemetryField::Latitude));
        const size_t countEnd = varintEnd(at + 1);
        size_t lengthAt = countEnd + 1, length = 0, shift = 0;
        for (; uchar(block[lengthAt]) & 0x80; ++lengthAt, shift += 7)
            length |= size_t(uchar(block[lengthAt]) & 0x7f) << shift;
        length |= size_t(uchar(block[lengthAt])) << shift;
        const size_t second = lengthAt + 1 + length;
        QCOMPARE(uchar(block[second]), uchar(TelemetryField::Longitude));
        block[second] = char(TelemetryField::Latitude);
        block.resize(block.size() - 4);
        const uint32_t crc = flightlog::crc32(block);
        block.append(reinterpret_cast<const char *>(&crc), 4);
        std::string error;
        QVERIFY(!TelemetryBlockCodec::decode(block, &error));
        QCOMPARE(error, std::string("a field twice in one block"));
        QVERIFY(!TelemetryBlockCodec::summarize(block, &error));
    }

    void crcIsIeee()
    {
        QCOMPARE(flightlog::crc32("123456789"), 0xCBF43926u);
    }
};

QTEST_APPLESS_MAIN(TestBlockCodec)
#include "tst_blockcodec.moc"
