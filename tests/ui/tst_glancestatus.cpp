// The glance bar's judgements (ui/instruments/GlanceStatus): each reading against its thresholds,
// pure, then a vehicle fed telemetry as a link would: missing until reported (never 0), then ok,
// warning and problem as its GPS, battery and link change.
#include "GlanceStatus.h"
#include "TelemetryField.h"
#include "TintedIcon.h"
#include "Vehicle.h"

#include <QGuiApplication>
#include <QTest>

using namespace sortie;
using ui::GlanceStatus;
using L = GlanceStatus::Level;
using F = vehicle::TelemetryField;

namespace {
// Positions `count` times, `stepMs` apart, from `time` on.
void positions(vehicle::Vehicle &v, int64_t time, int count, int stepMs)
{
    for (int i = 0; i < count; ++i)
        v.ingest({{F::Latitude, 56.95, time + i * stepMs}, {F::Longitude, 24.1, time + i * stepMs}});
}
} // namespace

class TestGlanceStatus : public QObject
{
    Q_OBJECT

private slots:
    void connection()
    {
        QCOMPARE(GlanceStatus::judgeConnection(QStringLiteral("Ready"), false), L::Ok);
        QCOMPARE(GlanceStatus::judgeConnection(QStringLiteral("Disconnected"), false), L::Missing); // not asked for
        QCOMPARE(GlanceStatus::judgeConnection(QStringLiteral("Disconnected"), true), L::Problem);  // refused, lost
        QCOMPARE(GlanceStatus::judgeConnection(QStringLiteral("Connecting"), false), L::Warning);
        QCOMPARE(GlanceStatus::judgeConnection(QStringLiteral("Reconnecting"), false), L::Warning);
        QCOMPARE(GlanceStatus::judgeConnection(QStringLiteral("Reconnecting"), true), L::Problem);
        QCOMPARE(GlanceStatus::judgeConnection(QString(), false), L::Missing);
    }

    void vehicleItself()
    {
        QCOMPARE(GlanceStatus::judgeVehicle(false, false, false, false), L::Missing);
        QCOMPARE(GlanceStatus::judgeVehicle(true, true, false, false), L::Ok);
        QCOMPARE(GlanceStatus::judgeVehicle(true, true, false, true), L::Warning);   // silent for a while
        QCOMPARE(GlanceStatus::judgeVehicle(true, false, false, false), L::Warning); // connecting
        QCOMPARE(GlanceStatus::judgeVehicle(true, false, true, false), L::Problem);  // link lost
    }

    void gps()
    {
        const GlanceStatus::Thresholds t;
        QCOMPARE(GlanceStatus::judgeGps(qQNaN(), qQNaN(), t), L::Missing);
        QCOMPARE(GlanceStatus::judgeGps(3, 12, t), L::Ok);
        QCOMPARE(GlanceStatus::judgeGps(5, t.warningSatellites, t), L::Ok);          // RTK fixed, at the threshold
        QCOMPARE(GlanceStatus::judgeGps(3, t.warningSatellites - 1, t), L::Warning); // few satellites
        QCOMPARE(GlanceStatus::judgeGps(3, t.problemSatellites - 1, t), L::Problem); // too few
        QCOMPARE(GlanceStatus::judgeGps(2, 12, t), L::Warning);                      // a 2D fix
        QCOMPARE(GlanceStatus::judgeGps(1, 12, t), L::Problem);                      // no fix
        QCOMPARE(GlanceStatus::judgeGps(0, qQNaN(), t), L::Problem);
        QCOMPARE(GlanceStatus::judgeGps(qQNaN(), 12, t), L::Warning);                // a count without a fix type
    }

    void battery()
    {
        using B = ui::FlightStatus::BatteryState;
        QCOMPARE(GlanceStatus::judgeBattery(B::Unknown), L::Missing);
        QCOMPARE(GlanceStatus::judgeBattery(B::Normal), L::Ok);
        QCOMPARE(GlanceStatus::judgeBattery(B::Low), L::Warning);
        QCOMPARE(GlanceStatus::judgeBattery(B::Critical), L::Problem);
        QCOMPARE(GlanceStatus::batteryIconFor(qQNaN()), QStringLiteral("battery-missing"));
        QCOMPARE(GlanceStatus::batteryIconFor(0.0), QStringLiteral("battery-level-0"));
        QCOMPARE(GlanceStatus::batteryIconFor(0.76), QStringLiteral("battery-level-80"));
        QCOMPARE(GlanceStatus::batteryIconFor(1.2), QStringLiteral("battery-level-100"));
    }

    void link()
    {
        const GlanceStatus::Thresholds t;
        QCOMPARE(GlanceStatus::judgeLink(qQNaN(), false, t), L::Missing);
        QCOMPARE(GlanceStatus::judgeLink(10, false, t), L::Ok);
        QCOMPARE(GlanceStatus::judgeLink(t.okRate, false, t), L::Ok);
        QCOMPARE(GlanceStatus::judgeLink(1.0, false, t), L::Warning);
        QCOMPARE(GlanceStatus::judgeLink(0.2, false, t), L::Problem);
        QCOMPARE(GlanceStatus::judgeLink(10, true, t), L::Problem); // lost, whatever came before
        QCOMPARE(GlanceStatus::linkIconFor(qQNaN(), false, t), QStringLiteral("network-wireless-offline"));
        QCOMPARE(GlanceStatus::linkIconFor(10, false, t), QStringLiteral("network-wireless-signal-excellent"));
        QCOMPARE(GlanceStatus::linkIconFor(0.2, false, t), QStringLiteral("network-wireless-signal-none"));
    }

    // Every icon a judgement names is one of the built-in ones, drawn in the colour asked for.
    void everyIconIsBuiltIn()
    {
        const GlanceStatus::Thresholds t;
        QStringList names = {QStringLiteral("network-server"), QStringLiteral("airplane-mode"),
                             QStringLiteral("location-services-active"), QStringLiteral("location-services-disabled")};
        for (double remaining : {qQNaN(), 0.0, 0.04, 0.15, 0.5, 0.96, 1.0})
            names << GlanceStatus::batteryIconFor(remaining);
        for (double rate : {qQNaN(), 0.1, 1.0, 1.5, 3.0, 10.0})
            names << GlanceStatus::linkIconFor(rate, false, t);
        for (const QString &name : names) {
            const QImage icon = ui::TintedIcon::tinted(name, QColor(0x1b, 0x5e, 0x20), 24);
            QVERIFY2(!icon.isNull(), qPrintable(name));
            QCOMPARE(icon.size(), QSize(24, 24));
            int drawn = 0;
            for (int y = 0; y < icon.height(); ++y)
                for (int x = 0; x < icon.width(); ++x) {
                    const QRgb p = icon.pixel(x, y);
                    drawn += qAlpha(p) > 64 ? 1 : 0; // Adwaita draws an icon's "off" parts translucent
                    // The icon's grey is gone: its opaque pixels are the colour (to rounding).
                    if (qAlpha(p) == 255)
                        QVERIFY2(std::abs(qRed(p) - 0x1b) <= 1 && std::abs(qGreen(p) - 0x5e) <= 1 && std::abs(qBlue(p) - 0x20) <= 1,
                                 qPrintable(name + QStringLiteral(": ") + QColor(p).name()));
                }
            QVERIFY2(drawn > 10, qPrintable(name)); // a shape, not an empty square
        }
        QVERIFY(ui::TintedIcon::tinted(QStringLiteral("no-such-icon"), Qt::red, 24).isNull());
    }

    void aVehicleMissingThenJudged()
    {
        GlanceStatus glance;
        // No fleet, no vehicle: everything missing, worded as missing.
        QCOMPARE(glance.vehicleLevel(), L::Missing);
        QCOMPARE(glance.gpsLevel(), L::Missing);
        QCOMPARE(glance.batteryLevel(), L::Missing);
        QCOMPARE(glance.linkLevel(), L::Missing);
        QCOMPARE(glance.connectionLevel(), L::Missing);

        vehicle::Vehicle v(nullptr);
        v.setNotifyInterval(0);
        glance.setChosen(&v);
        QCOMPARE(glance.vehicle(), &v);
        QCOMPARE(glance.gpsLevel(), L::Missing);
        QCOMPARE(glance.batteryLevel(), L::Missing);
        QVERIFY2(!glance.gpsText().contains(QLatin1Char('0')), qPrintable(glance.gpsText()));   // never "0 satellites"
        QVERIFY2(!glance.batteryText().contains(QLatin1Char('0')), qPrintable(glance.batteryText())); // never "0 %"
        QCOMPARE(glance.batteryIcon(), QStringLiteral("battery-missing"));

        v.ingest({{F::GpsFix, 3, 1000}, {F::Satellites, 12, 1000}, {F::BatteryRemaining, 0.76, 1000}});
        QTRY_COMPARE(glance.gpsLevel(), L::Ok);
        QCOMPARE(glance.gpsText(), QStringLiteral("3D fix, 12 sats"));
        QTRY_COMPARE(glance.batteryLevel(), L::Ok);
        QCOMPARE(glance.batteryText(), QStringLiteral("76 %"));
        QCOMPARE(glance.batteryIcon(), QStringLiteral("battery-level-80"));

        v.ingest({{F::Satellites, 6, 2000}, {F::BatteryRemaining, 0.2, 2000}});
        QTRY_COMPARE(glance.gpsLevel(), L::Warning);
        QTRY_COMPARE(glance.batteryLevel(), L::Warning);
        v.ingest({{F::GpsFix, 1, 3000}, {F::BatteryRemaining, 0.1, 3000}});
        QTRY_COMPARE(glance.gpsLevel(), L::Problem);
        QCOMPARE(glance.gpsText(), QStringLiteral("No fix, 6 sats"));
        QTRY_COMPARE(glance.batteryLevel(), L::Problem);

        // The link: ten positions a second over the last seconds is ok; none yet is missing.
        QCOMPARE(glance.linkLevel(), L::Missing);
        positions(v, 4000, 30, 100);
        QTRY_COMPARE(glance.linkLevel(), L::Ok);
        QCOMPARE(glance.linkIcon(), QStringLiteral("network-wireless-signal-excellent"));

        // The chosen vehicle gone: missing again.
        glance.setChosen(nullptr);
        QCOMPARE(glance.vehicleLevel(), L::Missing);
        QCOMPARE(glance.batteryLevel(), L::Missing);
    }
};

QTEST_MAIN(TestGlanceStatus)
#include "tst_glancestatus.moc"
