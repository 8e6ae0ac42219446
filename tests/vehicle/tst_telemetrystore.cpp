// TelemetrySeries and TelemetryStore: bounded ring buffers, ordered history, time-range queries.
#include "TelemetryStore.h"

#include <QtTest>

using namespace sortie::vehicle;

class TstTelemetryStore : public QObject
{
    Q_OBJECT
private slots:
    void seriesWrapsAtCapacity();
    void olderSamplesAreRejected();
    void rangeQueries();
    void storeAllocatesOnlyUsedFields();
    void batchIngest();
    void fieldNames();
};

void TstTelemetryStore::seriesWrapsAtCapacity()
{
    TelemetrySeries s(5);
    QVERIFY(s.empty());
    QCOMPARE(s.memoryBytes(), size_t(0));
    for (int i = 0; i < 12; ++i)
        QVERIFY(s.push(1000 + i, i * 1.5));
    QCOMPARE(s.size(), size_t(5));
    QCOMPARE(s.memoryBytes(), size_t(5 * 16));
    QCOMPARE(s.oldest().time, int64_t(1007));
    QCOMPARE(s.newest().time, int64_t(1011));
    QCOMPARE(s.newest().value, 11 * 1.5);
    for (size_t i = 0; i < s.size(); ++i)
        QCOMPARE(s.at(i).time, int64_t(1007 + i));
    s.clear();
    QVERIFY(s.empty());
    QVERIFY(s.push(5, 1)); // after clear, any time is fine again

    // Cleared while not yet full, then filled past capacity: still one ordered ring.
    TelemetrySeries partial(4);
    partial.push(1, 1);
    partial.push(2, 2);
    partial.clear();
    for (int i = 10; i < 16; ++i)
        QVERIFY(partial.push(i, i));
    QCOMPARE(partial.size(), size_t(4));
    for (size_t i = 0; i < partial.size(); ++i)
        QCOMPARE(partial.at(i).time, int64_t(12 + i));
    QCOMPARE(partial.memoryBytes(), size_t(4 * 16));
}

void TstTelemetryStore::olderSamplesAreRejected()
{
    TelemetrySeries s(10);
    QVERIFY(s.push(100, 1));
    QVERIFY(s.push(100, 2)); // same time: kept (a batch may carry several)
    QVERIFY(!s.push(99, 3));
    QCOMPARE(s.rejected(), uint64_t(1));
    QCOMPARE(s.size(), size_t(2));
    QCOMPARE(s.newest().value, 2.0);
    TelemetrySeries none(0);
    QVERIFY(!none.push(1, 1));
}

void TstTelemetryStore::rangeQueries()
{
    TelemetrySeries s(100);
    for (int i = 0; i < 250; ++i) // keeps 150..249
        s.push(i * 10, i);
    QCOMPARE(s.lowerBound(0), size_t(0));
    QCOMPARE(s.lowerBound(1500), size_t(0));
    QCOMPARE(s.lowerBound(1505), size_t(1));
    QCOMPARE(s.lowerBound(99999), size_t(100));
    std::vector<TelemetrySample> out;
    QCOMPARE(s.copyBetween(2000, 2100, out), size_t(11));
    QCOMPARE(out.front().value, 200.0);
    QCOMPARE(out.back().value, 210.0);
    out.clear();
    QCOMPARE(s.copyBetween(0, 1000, out), size_t(0));
    QCOMPARE(s.copyBetween(2485, 5000, out), size_t(1));
}

void TstTelemetryStore::storeAllocatesOnlyUsedFields()
{
    TelemetryStore store;
    QCOMPARE(store.capacityPerField(), size_t(18000));
    QCOMPARE(store.memoryBytes(), size_t(0));
    store.ingest(TelemetryField::Latitude, 1, 0.99);
    store.ingest(TelemetryField::GroundSpeed, 1, 4.0);
    QCOMPARE(store.memoryBytes(), 2 * TelemetryStore::memoryBytesPerField(18000));
    QCOMPARE(TelemetryStore::memoryBytesPerField(18000), size_t(288000));
    QCOMPARE(store.last(TelemetryField::GroundSpeed)->value, 4.0);
    QVERIFY(!store.last(TelemetryField::Roll));
    for (int i = 0; i < 40000; ++i)
        store.ingest(TelemetryField::Latitude, 2 + i, i);
    QCOMPARE(store.series(TelemetryField::Latitude).size(), size_t(18000)); // bounded
    QCOMPARE(store.memoryBytes(), 2 * TelemetryStore::memoryBytesPerField(18000));
    store.clear();
    QVERIFY(!store.last(TelemetryField::Latitude));
}

void TstTelemetryStore::batchIngest()
{
    TelemetryStore store(16);
    const TelemetryBatch batch = {{TelemetryField::Latitude, 0.5, 10}, {TelemetryField::Longitude, 0.4, 10},
                                  {TelemetryField::Latitude, 0.6, 20}};
    store.ingest(batch);
    QCOMPARE(store.series(TelemetryField::Latitude).size(), size_t(2));
    QCOMPARE(store.last(TelemetryField::Latitude)->time, int64_t(20));
    std::vector<TelemetrySample> out;
    QCOMPARE(store.copyBetween(TelemetryField::Longitude, 0, 100, out), size_t(1));
}

void TstTelemetryStore::fieldNames()
{
    for (size_t i = 0; i < kTelemetryFieldCount; ++i) {
        const auto f = TelemetryField(i);
        QCOMPARE(fieldFromName(fieldName(f)), std::optional<TelemetryField>(f));
    }
    QCOMPARE(fieldName(TelemetryField::GroundSpeed), std::string_view("groundSpeed"));
    QCOMPARE(fieldUnit(TelemetryField::Heading), std::string_view("deg"));
    QVERIFY(isAngle(TelemetryField::HomeLongitude) && isAngle(TelemetryField::Roll) && !isAngle(TelemetryField::AltitudeAgl));
    QVERIFY(!fieldFromName("warpFactor"));
    QVERIFY(modeFromName("return_home") == FlightMode::ReturnHome);
    QVERIFY(modeFromName("RTL") == FlightMode::ReturnHome);
    QVERIFY(modeFromName("loiter") == FlightMode::Hold);
    QVERIFY(modeFromName("Mission") == FlightMode::Auto);
    QVERIFY(modeFromName("teleport") == FlightMode::Unknown);
    QCOMPARE(modeName(FlightMode::Guided), std::string_view("guided"));
    QVERIFY(missionStateFromName("complete") == MissionState::Complete);
}

QTEST_GUILESS_MAIN(TstTelemetryStore)
#include "tst_telemetrystore.moc"
