// Vehicle: last values, coalesced notifications for QML, stale detection, history; and the VCI
// telemetry mapping that feeds it.
#include "Vehicle.h"
#include "VciTelemetryMapper.h"

#include <QSignalSpy>
#include <QtTest>

using nlohmann::json;
using namespace sortie::vehicle;

class TstVehicle : public QObject
{
    Q_OBJECT
private slots:
    void lastValuesAndProperties();
    void notificationsAreCoalesced();
    void repeatedValuesNotifyOnlyTheHistory();
    void staleDetection();
    void historyIsFilled();
    void vciMapping();
};

void TstVehicle::lastValuesAndProperties()
{
    Vehicle v(nullptr);
    QVERIFY(!v.position().isValid());
    QVERIFY(std::isnan(v.groundSpeed()));
    QCOMPARE(v.mode(), QStringLiteral("unknown"));
    // Angles in degrees, as every link delivers them.
    v.ingest({{TelemetryField::Latitude, 56.95, 1000}, {TelemetryField::Longitude, 24.1, 1000},
              {TelemetryField::AltitudeAmsl, 120, 1000}, {TelemetryField::GroundSpeed, 7.5, 1000},
              {TelemetryField::Armed, 1, 1000}, {TelemetryField::Mode, double(FlightMode::ReturnHome), 1000},
              {TelemetryField::MissionState, double(MissionState::Paused), 1000}, {TelemetryField::Satellites, 12, 1000}});
    QVERIFY(std::abs(v.position().latitude() - 56.95) < 1e-9);
    QCOMPARE(v.position().altitude(), 120.0);
    QCOMPARE(v.groundSpeed(), 7.5);
    QVERIFY(v.armed());
    QCOMPARE(v.mode(), QStringLiteral("return_home"));
    QCOMPARE(v.missionState(), QStringLiteral("paused"));
    QCOMPARE(v.satellites(), 12);
    QCOMPARE(v.value(QStringLiteral("groundSpeed")), 7.5);
    QVERIFY(std::isnan(v.value(QStringLiteral("nonsense"))));
    QCOMPARE(v.last(TelemetryField::GroundSpeed)->time, int64_t(1000));
    // The QML-facing property names resolve through the meta-object.
    QCOMPARE(v.property("groundSpeed").toDouble(), 7.5);
    QCOMPARE(v.property("mode").toString(), QStringLiteral("return_home"));
    QVERIFY(v.property("position").value<QGeoCoordinate>().isValid());
}

void TstVehicle::notificationsAreCoalesced()
{
    Vehicle v(nullptr);
    v.setNotifyInterval(50);
    QSignalSpy changed(&v, &Vehicle::telemetryChanged);
    for (int i = 0; i < 1000; ++i) // 1,000 batches without the event loop running in between
        v.ingest({{TelemetryField::GroundSpeed, double(i), 1000 + i}});
    QCOMPARE(changed.count(), 1); // the first at once
    QCOMPARE(v.groundSpeed(), 999.0); // the values themselves are always current
    QTRY_COMPARE(changed.count(), 2); // the rest gathered into one
    // Nothing new, nothing sent: no notification waits, and only an ingest makes one.
    QVERIFY(!v.notificationPending());
    QCOMPARE(changed.count(), 2);
    QCOMPARE(v.telemetryNotifications(), quint64(2));
}

// A parked vehicle repeats its values with later times: the properties QML binds to have not
// changed (no telemetryChanged, so nothing redraws for it), the history has (historyChanged, for the
// plots). A changed value is a telemetryChanged again; NaN (a value the vehicle lacks) repeated is none.
void TstVehicle::repeatedValuesNotifyOnlyTheHistory()
{
    Vehicle v(nullptr);
    v.setNotifyInterval(0);
    QSignalSpy values(&v, &Vehicle::telemetryChanged);
    QSignalSpy history(&v, &Vehicle::historyChanged);
    const auto parked = [](int64_t time) {
        return TelemetryBatch{{TelemetryField::Latitude, 56.95, time}, {TelemetryField::Longitude, 24.1, time},
                              {TelemetryField::Heading, 90, time}, {TelemetryField::AltitudeAgl, qQNaN(), time}};
    };
    v.ingest(parked(1000));
    QCOMPARE(values.count(), 1); // the first values are news
    QCOMPARE(history.count(), 1);
    for (int i = 1; i <= 30; ++i)
        v.ingest(parked(1000 + 100 * i));
    QCOMPARE(values.count(), 1);
    QCOMPARE(history.count(), 31);
    QCOMPARE(v.history().series(TelemetryField::Latitude).size(), size_t(31));
    QCOMPARE(v.last(TelemetryField::Latitude)->time, int64_t(4000)); // the time is always current
    QCOMPARE(v.telemetryNotifications(), quint64(1));
    v.ingest({{TelemetryField::Heading, 91, 4100}});
    QCOMPARE(values.count(), 2);
    QCOMPARE(v.heading(), 91.0);
}

void TstVehicle::staleDetection()
{
    Vehicle v(nullptr);
    v.setStaleAfter(100);
    QVERIFY(v.isStale());
    QVERIFY(v.isStale(TelemetryField::Latitude));
    QSignalSpy staleChanged(&v, &Vehicle::staleChanged);
    v.ingest({{TelemetryField::Latitude, 1, 1}});
    QVERIFY(!v.isStale());
    QVERIFY(!v.isStale(TelemetryField::Latitude));
    QVERIFY(v.isStale(TelemetryField::Longitude)); // never received
    QVERIFY(!v.isFieldStale(QStringLiteral("latitude")));
    QTRY_VERIFY(staleChanged.count() >= 1);
    QTRY_VERIFY(v.isStale());
    QVERIFY(v.isStale(TelemetryField::Latitude));
    QVERIFY(v.isFieldStale(QStringLiteral("latitude")));
    const qsizetype before = staleChanged.count();
    v.ingest({{TelemetryField::Latitude, 2, 2}});
    QVERIFY(!v.isStale());
    QTRY_VERIFY(staleChanged.count() > before);
}

void TstVehicle::historyIsFilled()
{
    Vehicle v(nullptr, nullptr, 100);
    for (int i = 0; i < 150; ++i)
        v.ingest({{TelemetryField::AltitudeAgl, double(i), 10 * i}, {TelemetryField::Roll, 0.1, 10 * i}});
    QCOMPARE(v.history().series(TelemetryField::AltitudeAgl).size(), size_t(100));
    QCOMPARE(v.history().last(TelemetryField::AltitudeAgl)->value, 149.0);
    std::vector<TelemetrySample> window;
    QCOMPARE(v.history().copyBetween(TelemetryField::AltitudeAgl, 1400, 1490, window), size_t(10));
}

void TstVehicle::vciMapping()
{
    auto find = [](const TelemetryBatch &b, TelemetryField f) -> std::optional<TelemetryUpdate> {
        for (const auto &u : b) {
            if (u.field == f)
                return u;
        }
        return std::nullopt;
    };
    auto b = vciTelemetry("/telemetry/position", json{{"latitude", 0.99}, {"longitude", 0.42}, {"altitudeAmsl", 100}, {"time", 1234}}, 9);
    QCOMPARE(b.size(), size_t(3));
    // The profile's radians become degrees here, once.
    QVERIFY(std::abs(find(b, TelemetryField::Latitude)->value - 0.99 * 180 / M_PI) < 1e-12);
    QCOMPARE(find(b, TelemetryField::AltitudeAmsl)->value, 100.0);
    QCOMPARE(find(b, TelemetryField::Latitude)->time, int64_t(1234));
    b = vciTelemetry("/telemetry/attitude", json{{"roll", 0.1}, {"pitch", "bad"}, {"yaw", 3.0}}, 9);
    QCOMPARE(b.size(), size_t(2)); // a field of the wrong type is skipped
    QVERIFY(std::abs(find(b, TelemetryField::Heading)->value - 3.0 * 180 / M_PI) < 1e-12);
    QVERIFY(std::abs(find(b, TelemetryField::Roll)->value - 0.1 * 180 / M_PI) < 1e-12);
    QCOMPARE(find(b, TelemetryField::Heading)->time, int64_t(9)); // no "time": when it arrived
    b = vciTelemetry("/telemetry/speed", json{{"ground", 5}, {"air", 6}, {"vertical", -1}, {"course", 1.5}}, 9);
    QCOMPARE(b.size(), size_t(4));
    QCOMPARE(find(b, TelemetryField::GroundSpeed)->value, 5.0);
    QVERIFY(std::abs(find(b, TelemetryField::Course)->value - 1.5 * 180 / M_PI) < 1e-12);
    b = vciTelemetry("/telemetry/battery", json{{"voltage", 15.2}, {"current", 9}, {"remaining", 0.8}}, 9);
    QCOMPARE(find(b, TelemetryField::BatteryRemaining)->value, 0.8);
    b = vciTelemetry("/telemetry/gps", json{{"fix", 3}, {"satellites", 14}, {"hdop", 0.8}}, 9);
    QCOMPARE(find(b, TelemetryField::Satellites)->value, 14.0);
    b = vciTelemetry("/telemetry/home", json{{"latitude", 0.5}, {"longitude", 0.6}, {"altitudeAmsl", 12}}, 9);
    QCOMPARE(find(b, TelemetryField::HomeAltitudeAmsl)->value, 12.0);
    b = vciTelemetry("/state/armed", json(true), 9);
    QCOMPARE(find(b, TelemetryField::Armed)->value, 1.0);
    b = vciTelemetry("/state/mode", json("loiter"), 9);
    QCOMPARE(find(b, TelemetryField::Mode)->value, double(FlightMode::Hold));
    b = vciTelemetry("/mission/progress", json{{"state", "active"}, {"current", 2}, {"reached", 2}, {"count", 5}}, 9);
    QCOMPARE(b.size(), size_t(4));
    QCOMPARE(find(b, TelemetryField::MissionState)->value, double(MissionState::Active));
    QVERIFY(vciTelemetry("/telemetry/position", json::array({1, 2}), 9).empty());
    QVERIFY(vciTelemetry("/vehicle", json{{"id", "x"}}, 9).empty());
    QVERIFY(vciTelemetry("/state/armed", json("yes"), 9).empty());
    // What fuzz_vci_telemetry found: a time no int64 holds is the arrival time (converting it was
    // undefined), and a value infinite once in degrees is no reading.
    b = vciTelemetry("/telemetry/attitude", json{{"roll", 0.1}, {"yaw", 1e308}, {"time", 1e300}}, 9);
    QCOMPARE(b.size(), size_t(1));
    QCOMPARE(b.front().field, TelemetryField::Roll);
    QCOMPARE(b.front().time, int64_t(9));
    b = vciTelemetry("/telemetry/position", json{{"latitude", 0.5}, {"time", 18446744073709551615ULL}}, 9);
    QCOMPARE(b.front().time, int64_t(9));
    b = vciTelemetry("/telemetry/position", json{{"latitude", 0.5}, {"time", 1764670000000.7}}, 9);
    QCOMPARE(b.front().time, int64_t(1764670000000));
}

QTEST_GUILESS_MAIN(TstVehicle)
#include "tst_vehicle.moc"
