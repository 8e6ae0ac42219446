#include "GamepadSettings.h"

#include "Gamepad.h"
#include "GamepadLog.h"

#include <QSettings>

#include <algorithm>

namespace sortie::gamepad {

GamepadSettings::GamepadSettings(QSettings *settings, const QString &group, const QString &guid, QObject *parent)
    : QObject(parent), m_settings(settings), m_guid(guid)
{
    Q_ASSERT(m_settings);
    m_prefix = group.isEmpty() ? guid + QLatin1Char('/') : group + QLatin1Char('/') + guid + QLatin1Char('/');
    load();
}

GamepadSettings::~GamepadSettings()
{
    // No calibrationChanged from a destructor: the connections go with this object.
    QObject::disconnect(m_sampling);
    QObject::disconnect(m_calibrationLost);
}

AxisShaping GamepadSettings::defaultShaping(Axis axis)
{
    AxisShaping shaping;
    if (isTrigger(axis)) {
        shaping.calibration = kTriggerCalibration;
        shaping.deadZone = 0.02;
    } else {
        shaping.deadZone = 0.05;
    }
    return shaping;
}

QString GamepadSettings::defaultAction(Button button)
{
    switch (button) {
    case Button::Start: return QStringLiteral("arm");
    case Button::A: return QStringLiteral("photo");
    case Button::B: return QStringLiteral("returnHome");
    case Button::X: return QStringLiteral("hold");
    case Button::Y: return QStringLiteral("land");
    default: return {};
    }
}

QString GamepadSettings::axisKey(Axis axis, const char *field) const
{
    return m_prefix + QStringLiteral("axes/") + axisName(axis) + QLatin1Char('/') + QLatin1String(field);
}

QString GamepadSettings::buttonKey(Button button) const
{
    return m_prefix + QStringLiteral("buttons/") + buttonName(button);
}

void GamepadSettings::load()
{
    for (int i = 0; i < kAxisCount; ++i) {
        const Axis axis = Axis(i);
        AxisShaping s = defaultShaping(axis);
        s.deadZone = clampUnit(m_settings->value(axisKey(axis, "deadZone"), s.deadZone).toDouble(), 0.0, kMaxDeadZone);
        s.expo = clampUnit(m_settings->value(axisKey(axis, "expo"), s.expo).toDouble(), 0.0, 1.0);
        AxisCalibration c;
        c.min = m_settings->value(axisKey(axis, "min"), s.calibration.min).toInt();
        c.centre = m_settings->value(axisKey(axis, "centre"), s.calibration.centre).toInt();
        c.max = m_settings->value(axisKey(axis, "max"), s.calibration.max).toInt();
        if (c.min <= c.centre && c.centre < c.max) {
            s.calibration = c;
        } else {
            qCWarning(lcGamepad) << "gamepad" << m_guid << axisName(axis) << "calibration" << c.min << c.centre << c.max
                                 << "is not min <= centre < max: the default instead";
        }
        m_shaping[i] = s;
    }
    for (int i = 0; i < kButtonCount; ++i) {
        const Button button = Button(i);
        // A key saved empty is "no action", not the default.
        const QString key = buttonKey(button);
        m_actions[i] = m_settings->contains(key) ? m_settings->value(key).toString() : defaultAction(button);
    }
}

void GamepadSettings::storeShaping(Axis axis)
{
    const AxisShaping &s = m_shaping[int(axis)];
    m_settings->setValue(axisKey(axis, "deadZone"), s.deadZone);
    m_settings->setValue(axisKey(axis, "expo"), s.expo);
    m_settings->setValue(axisKey(axis, "min"), s.calibration.min);
    m_settings->setValue(axisKey(axis, "centre"), s.calibration.centre);
    m_settings->setValue(axisKey(axis, "max"), s.calibration.max);
}

void GamepadSettings::setShaping(Axis axis, const AxisShaping &shaping)
{
    AxisShaping s = shaping;
    s.deadZone = clampUnit(s.deadZone, 0.0, kMaxDeadZone);
    s.expo = clampUnit(s.expo, 0.0, 1.0);
    if (!(s.calibration.min <= s.calibration.centre && s.calibration.centre < s.calibration.max)) {
        qCWarning(lcGamepad) << "gamepad" << m_guid << axisName(axis) << "calibration refused:" << s.calibration.min
                             << s.calibration.centre << s.calibration.max;
        s.calibration = m_shaping[int(axis)].calibration;
    }
    if (m_shaping[int(axis)] == s)
        return;
    m_shaping[int(axis)] = s;
    storeShaping(axis);
    emit changed();
}

void GamepadSettings::setDeadZone(Axis axis, double deadZone)
{
    AxisShaping s = m_shaping[int(axis)];
    s.deadZone = deadZone;
    setShaping(axis, s);
}

void GamepadSettings::setExpo(Axis axis, double expo)
{
    AxisShaping s = m_shaping[int(axis)];
    s.expo = expo;
    setShaping(axis, s);
}

void GamepadSettings::setCalibration(Axis axis, const AxisCalibration &calibration)
{
    AxisShaping s = m_shaping[int(axis)];
    s.calibration = calibration;
    setShaping(axis, s);
}

void GamepadSettings::setAction(Button button, const QString &action)
{
    const QString trimmed = action.trimmed();
    // Saved even when it is the default: the operator's choice stays if the defaults change.
    m_settings->setValue(buttonKey(button), trimmed);
    if (m_actions[int(button)] == trimmed)
        return;
    m_actions[int(button)] = trimmed;
    emit changed();
}

QList<Button> GamepadSettings::buttonsFor(const QString &action) const
{
    QList<Button> buttons;
    if (action.isEmpty())
        return buttons;
    for (int i = 0; i < kButtonCount; ++i) {
        if (m_actions[i] == action)
            buttons.append(Button(i));
    }
    return buttons;
}

void GamepadSettings::resetToDefaults()
{
    m_settings->remove(m_prefix.chopped(1));
    const auto before = m_shaping;
    const auto actionsBefore = m_actions;
    load();
    if (before != m_shaping || actionsBefore != m_actions)
        emit changed();
}

void GamepadSettings::bind(Gamepad *pad)
{
    if (!pad)
        return;
    const auto apply = [this, pad] {
        for (int i = 0; i < kAxisCount; ++i)
            pad->setShaping(Axis(i), m_shaping[i]);
    };
    apply();
    connect(this, &GamepadSettings::changed, pad, apply);
}

void GamepadSettings::beginCalibration(Gamepad *pad)
{
    cancelCalibration();
    if (!pad || !pad->isAttached())
        return;
    m_calibrationPad = pad;
    for (int i = 0; i < kAxisCount; ++i) {
        const int raw = pad->rawAxis(Axis(i));
        m_measured[i] = AxisCalibration{raw, raw, raw};
    }
    m_sampling = connect(pad, &Gamepad::axesChanged, this, &GamepadSettings::sample);
    m_calibrationLost = connect(pad, &Gamepad::detached, this, &GamepadSettings::cancelCalibration);
    qCInfo(lcGamepad) << "calibrating" << pad->name() << m_guid;
    emit calibratingChanged();
}

void GamepadSettings::sample()
{
    if (!m_calibrationPad || !m_calibrationPad->isAttached())
        return;
    for (int i = 0; i < kAxisCount; ++i) {
        const int raw = m_calibrationPad->rawAxis(Axis(i));
        m_measured[i].min = std::min(m_measured[i].min, raw);
        m_measured[i].max = std::max(m_measured[i].max, raw);
    }
}

QList<Axis> GamepadSettings::finishCalibration()
{
    QList<Axis> calibrated;
    if (!isCalibrating())
        return calibrated;
    sample();
    const auto measured = m_measured;
    cancelCalibration();
    for (int i = 0; i < kAxisCount; ++i) {
        const Axis axis = Axis(i);
        AxisCalibration c = measured[i];
        bool enough = c.max - c.centre >= kMinCalibrationSpan;
        if (isTrigger(axis))
            c.min = c.centre;  // a trigger rests at its low end
        else
            enough = enough && c.centre - c.min >= kMinCalibrationSpan;
        if (!enough) {
            qCInfo(lcGamepad) << "calibration:" << axisName(axis) << "not moved to its ends (" << c.min << c.centre
                              << c.max << "): its calibration kept";
            continue;
        }
        setCalibration(axis, c);
        calibrated.append(axis);
    }
    qCInfo(lcGamepad) << "calibration of" << m_guid << "stored for" << calibrated.size() << "axes";
    return calibrated;
}

void GamepadSettings::cancelCalibration()
{
    if (!isCalibrating() && !m_sampling)
        return;
    QObject::disconnect(m_sampling);
    QObject::disconnect(m_calibrationLost);
    m_calibrationPad.clear();
    emit calibratingChanged();
}

} // namespace sortie::gamepad
