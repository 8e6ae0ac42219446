// The sticks' shaping (core/gamepad's StickShaping.h, docs/gamepad.md "Shaping"): calibration,
// dead zone and expo, each formula with exact values, and the whole chain continuous and monotonic
// over SDL's raw range.
#include "Gamepad.h"
#include "GamepadControls.h"
#include "StickShaping.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace sortie::gamepad;

class TestStickShaping : public QObject
{
    Q_OBJECT

private slots:
    void defaultCalibrationCoversSdlsRange()
    {
        const AxisCalibration c;
        QCOMPARE(normalise(kRawMax, c), 1.0);
        QCOMPARE(normalise(kRawMin, c), -1.0);
        QCOMPARE(normalise(0, c), 0.0);
        QCOMPARE(normalise(16384, c), 16384.0 / 32767.0);
        QCOMPARE(normalise(-16384, c), -0.5);  // the negative side is 32768 wide
    }

    void calibrationEachSideOnItsOwn()
    {
        // A stick resting at 100 that reaches -800 and 1100.
        const AxisCalibration c{-800, 100, 1100};
        QCOMPARE(normalise(100, c), 0.0);
        QCOMPARE(normalise(600, c), 0.5);
        QCOMPARE(normalise(1100, c), 1.0);
        QCOMPARE(normalise(-350, c), -0.5);
        QCOMPARE(normalise(-800, c), -1.0);
        // Beyond what the calibration measured: held at the ends.
        QCOMPARE(normalise(30000, c), 1.0);
        QCOMPARE(normalise(-30000, c), -1.0);
    }

    void triggerHasNoNegativeSide()
    {
        QCOMPARE(normalise(0, kTriggerCalibration), 0.0);
        QCOMPARE(normalise(-100, kTriggerCalibration), 0.0);
        QCOMPARE(normalise(kRawMax, kTriggerCalibration), 1.0);
        // A calibration of no width at all reads 0, never a division by zero.
        QCOMPARE(normalise(5, AxisCalibration{0, 0, 0}), 0.0);
    }

    void deadZoneRescaledFromItsEdge()
    {
        QCOMPARE(applyDeadZone(0.0, 0.2), 0.0);
        QCOMPARE(applyDeadZone(0.1, 0.2), 0.0);
        QCOMPARE(applyDeadZone(-0.2, 0.2), 0.0);  // the edge itself reads 0
        QCOMPARE(applyDeadZone(0.6, 0.2), 0.5);
        QCOMPARE(applyDeadZone(-0.6, 0.2), -0.5);
        QCOMPARE(applyDeadZone(1.0, 0.2), 1.0);
        QCOMPARE(applyDeadZone(-1.0, 0.2), -1.0);
        // Continuous: just past the edge is just past 0, not a jump to 0.2.
        QVERIFY(applyDeadZone(0.2 + 1e-9, 0.2) < 1e-8);
        // No dead zone: the value itself.
        QCOMPARE(applyDeadZone(0.3, 0.0), 0.3);
    }

    void deadZoneHeldToHalf()
    {
        QCOMPARE(applyDeadZone(0.75, 0.8), 0.5);  // taken as 0.5
        QCOMPARE(applyDeadZone(0.4, 0.8), 0.0);
        QCOMPARE(applyDeadZone(0.3, -1.0), 0.3);  // below 0: none
        QCOMPARE(applyDeadZone(0.3, std::nan("")), 0.3);
    }

    void expo()
    {
        QCOMPARE(applyExpo(0.5, 0.0), 0.5);
        QCOMPARE(applyExpo(0.5, 0.5), 0.3125);  // 0.5·0.5 + 0.5·0.125
        QCOMPARE(applyExpo(-0.5, 0.5), -0.3125);
        QCOMPARE(applyExpo(0.5, 1.0), 0.125);
        QCOMPARE(applyExpo(1.0, 0.7), 1.0);
        QCOMPARE(applyExpo(-1.0, 0.7), -1.0);
        QCOMPARE(applyExpo(0.5, 2.0), 0.125);  // held to 1
        QCOMPARE(applyExpo(0.5, -1.0), 0.5);   // held to 0
    }

    void wholeChain()
    {
        const AxisShaping s{{-1000, 0, 1000}, 0.2, 0.5};
        QCOMPARE(shape(600, s), 0.3125);   // 0.6 -> dead zone 0.5 -> expo 0.3125
        QCOMPARE(shape(-600, s), -0.3125);
        QCOMPARE(shape(150, s), 0.0);
        QCOMPARE(shape(1000, s), 1.0);
        QCOMPARE(shape(-32768, s), -1.0);
    }

    void continuousAndMonotonicOverTheRawRange()
    {
        const AxisShaping s{{-30000, 500, 31000}, 0.1, 0.4};
        double previous = shape(kRawMin, s);
        QCOMPARE(previous, -1.0);
        double largestStep = 0.0;
        for (int raw = kRawMin + 1; raw <= kRawMax; ++raw) {
            const double out = shape(raw, s);
            if (out < previous || out < -1.0 || out > 1.0)
                QFAIL(qPrintable(QStringLiteral("%1 at raw %2, after %3").arg(out).arg(raw).arg(previous)));
            largestStep = std::max(largestStep, out - previous);
            previous = out;
        }
        QCOMPARE(previous, 1.0);
        // No jump anywhere (a dead zone not rescaled would jump by 0.1 at its edge).
        QVERIFY2(largestStep < 1e-3, qPrintable(QString::number(largestStep)));
    }

    // Gamepad (no SDL: fed by hand) reads its raw values through its shaping, and detached reads 0.
    void gamepadShapesAndCentresWhenDetached()
    {
        Gamepad pad(7, QStringLiteral("Test pad"), QStringLiteral("00ff"));
        QSignalSpy axes(&pad, &Gamepad::axesChanged);
        QSignalSpy released(&pad, &Gamepad::buttonReleased);
        QSignalSpy detached(&pad, &Gamepad::detached);
        pad.setShaping(Axis::LeftX, AxisShaping{{-1000, 0, 1000}, 0.2, 0.5});
        QCOMPARE(axes.count(), 1);
        pad.setRawAxis(Axis::LeftX, 600);
        pad.setRawAxis(Axis::TriggerRight, kRawMax);
        QCOMPARE(axes.count(), 1);  // announced by the flush, once
        pad.flushAxes();
        QCOMPARE(axes.count(), 2);
        QCOMPARE(pad.axis(Axis::LeftX), 0.3125);
        QCOMPARE(pad.axis(Axis::TriggerRight), 1.0);
        QCOMPARE(pad.axis(Axis::TriggerLeft), 0.0);
        pad.setButton(Button::Start, true);
        QVERIFY(pad.button(Button::Start));

        pad.markDetached();
        QCOMPARE(pad.axis(Axis::LeftX), 0.0);
        QCOMPARE(pad.axis(Axis::TriggerRight), 0.0);
        QVERIFY(!pad.button(Button::Start));
        QCOMPARE(released.count(), 1);
        QCOMPARE(released.at(0).at(0).value<Button>(), Button::Start);
        QCOMPARE(detached.count(), 1);
        QCOMPARE(axes.count(), 3);
        // Nothing moves it any more.
        pad.setRawAxis(Axis::LeftX, 1000);
        pad.flushAxes();
        QCOMPARE(pad.axis(Axis::LeftX), 0.0);
    }

    void namesRoundTrip()
    {
        QCOMPARE(axisName(Axis::TriggerLeft), QStringLiteral("TriggerLeft"));
        QCOMPARE(buttonName(Button::DpadUp), QStringLiteral("DpadUp"));
        QVERIFY(axisFromName(QStringLiteral("RightY")) == std::optional<Axis>(Axis::RightY));
        QVERIFY(buttonFromName(QStringLiteral("Start")) == std::optional<Button>(Button::Start));
        QVERIFY(!buttonFromName(QStringLiteral("Fire")));
        for (int i = 0; i < kButtonCount; ++i)
            QVERIFY(buttonFromName(buttonName(Button(i))) == std::optional<Button>(Button(i)));
    }
};

QTEST_GUILESS_MAIN(TestStickShaping)
#include "tst_stickshaping.moc"
