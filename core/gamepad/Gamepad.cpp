#include "Gamepad.h"

#include "GamepadLog.h"

namespace sortie::gamepad {

Gamepad::Gamepad(int instanceId, const QString &name, const QString &guid, QObject *parent)
    : QObject(parent), m_instanceId(instanceId), m_name(name), m_guid(guid)
{
    for (int i = 0; i < kAxisCount; ++i)
        m_shaping[i] = defaultShaping(Axis(i));
}

AxisShaping Gamepad::defaultShaping(Axis axis)
{
    AxisShaping shaping;
    if (isTrigger(axis))
        shaping.calibration = kTriggerCalibration;
    return shaping;
}

double Gamepad::axis(Axis axis) const
{
    if (!m_attached)
        return 0.0;
    return shape(m_raw[index(axis)], m_shaping[index(axis)]);
}

void Gamepad::setShaping(Axis axis, const AxisShaping &shaping)
{
    if (m_shaping[index(axis)] == shaping)
        return;
    m_shaping[index(axis)] = shaping;
    if (m_attached)
        emit axesChanged();
}

void Gamepad::setRawAxis(Axis axis, int raw)
{
    if (!m_attached || m_raw[index(axis)] == raw)
        return;
    m_raw[index(axis)] = raw;
    m_axesDirty = true;
}

void Gamepad::flushAxes()
{
    if (!m_axesDirty)
        return;
    m_axesDirty = false;
    emit axesChanged();
}

void Gamepad::setButton(Button button, bool down, bool announce)
{
    if (!m_attached || m_buttons[index(button)] == down)
        return;
    m_buttons[index(button)] = down;
    if (!announce)
        return;
    if (down)
        emit buttonPressed(button);
    else
        emit buttonReleased(button);
}

void Gamepad::markDetached()
{
    if (!m_attached)
        return;
    qCInfo(lcGamepad) << "gamepad" << m_name << m_guid << "detached: its sticks read centred";
    // The held buttons first, while the gamepad still reads attached to whoever asks in their slots.
    for (int i = 0; i < kButtonCount; ++i) {
        if (m_buttons[i])
            setButton(Button(i), false);
    }
    m_attached = false;
    m_axesDirty = false;
    m_raw.fill(0);
    emit axesChanged();
    emit detached();
}

} // namespace sortie::gamepad
