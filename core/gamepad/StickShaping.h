#pragma once

// A stick's (or a trigger's) raw value made into the operator's -1..+1 (docs/gamepad.md, "Shaping"):
// pure, Qt-free and constexpr, so that the formulas are tested with exact values
// (tests/gamepad/tst_stickshaping.cpp) and hold at compile time (the static_asserts below).
//
//   normalise: the calibration's centre is 0, its max +1, its min -1, each side linear on its own
//              (a stick whose centre is off the middle still reaches ±1); beyond min or max, ±1.
//              A side of no width (a trigger: min == centre) reads 0.
//   dead zone: |x| <= d reads 0; beyond it, sign(x)·(|x| - d)/(1 - d), so the output rises from 0 at
//              the dead zone's edge and still reaches ±1 (d is held to 0..0.5).
//   expo:      (1 - e)·x + e·x³ (e held to 0..1): finer control near the centre, ±1 still ±1.
namespace sortie::gamepad {

// SDL's raw range for a stick's axis; a game controller's trigger reads 0..32767.
inline constexpr int kRawMin = -32768;
inline constexpr int kRawMax = 32767;
inline constexpr double kMaxDeadZone = 0.5;

// What a calibration measured: the raw value at each end and at rest.
struct AxisCalibration
{
    int min = kRawMin;
    int centre = 0;
    int max = kRawMax;

    friend constexpr bool operator==(const AxisCalibration &, const AxisCalibration &) = default;
};

// A trigger rests at its low end: min and centre are the same.
inline constexpr AxisCalibration kTriggerCalibration{0, 0, kRawMax};

struct AxisShaping
{
    AxisCalibration calibration;
    double deadZone = 0.0;  // 0..0.5 of the normalised range
    double expo = 0.0;      // 0..1

    friend constexpr bool operator==(const AxisShaping &, const AxisShaping &) = default;
};

constexpr double clampUnit(double x, double low, double high)
{
    // NaN compares false both ways: it reads as the low bound.
    return x > high ? high : (x >= low ? x : low);
}

constexpr double normalise(int raw, const AxisCalibration &c)
{
    if (raw >= c.centre) {
        const double span = double(c.max) - double(c.centre);
        if (span <= 0.0)
            return 0.0;
        const double v = (double(raw) - double(c.centre)) / span;
        return v > 1.0 ? 1.0 : v;
    }
    const double span = double(c.centre) - double(c.min);
    if (span <= 0.0)
        return 0.0;
    const double v = (double(raw) - double(c.centre)) / span;
    return v < -1.0 ? -1.0 : v;
}

constexpr double applyDeadZone(double x, double deadZone)
{
    const double d = clampUnit(deadZone, 0.0, kMaxDeadZone);
    const double a = x < 0.0 ? -x : x;
    if (a <= d)
        return 0.0;
    const double out = (a - d) / (1.0 - d);
    return x < 0.0 ? -out : out;
}

constexpr double applyExpo(double x, double expo)
{
    const double e = clampUnit(expo, 0.0, 1.0);
    return (1.0 - e) * x + e * x * x * x;
}

// The whole chain: calibration, then the dead zone, then expo.
constexpr double shape(int raw, const AxisShaping &s)
{
    return applyExpo(applyDeadZone(normalise(raw, s.calibration), s.deadZone), s.expo);
}

static_assert(shape(kRawMax, AxisShaping{}) == 1.0);
static_assert(shape(kRawMin, AxisShaping{}) == -1.0);
static_assert(shape(0, AxisShaping{{}, 0.1, 0.5}) == 0.0);
static_assert(applyExpo(0.5, 1.0) == 0.125);

} // namespace sortie::gamepad
