#pragma once

#include "GamepadControls.h"
#include "StickShaping.h"

#include <QObject>
#include <QString>

#include <array>

namespace sortie::gamepad {

// One attached gamepad's state, in our own names (no SDL here: GamepadManager feeds it from SDL's
// events, a test may feed it directly). axis() is shaped (StickShaping.h) by the shaping set per
// axis (GamepadSettings::bind sets the operator's); rawAxis() is SDL's value, for calibration.
//
// The rule "sticks centred when the gamepad disappears": once detached (markDetached, called by
// the manager when SDL reports the device gone), every axis reads 0 whatever its last raw value,
// the buttons still held are released (buttonReleased for each), axesChanged() and then detached()
// are emitted. The manager deletes the object later (deleteLater): hold it in a QPointer.
class Gamepad : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QString name READ name CONSTANT FINAL)
    Q_PROPERTY(QString guid READ guid CONSTANT FINAL)
    Q_PROPERTY(bool attached READ isAttached NOTIFY detached FINAL)

public:
    Gamepad(int instanceId, const QString &name, const QString &guid, QObject *parent = nullptr);

    // SDL's joystick instance id: unique for the device while it is attached.
    int instanceId() const { return m_instanceId; }
    QString name() const { return m_name; }
    // SDL's GUID as 32 hex digits: the same for every gamepad of one model and connection, which is
    // what the settings are kept by.
    QString guid() const { return m_guid; }
    bool isAttached() const { return m_attached; }

    // -1..+1 (a trigger 0..+1), shaped; 0 once detached.
    Q_INVOKABLE double axis(sortie::gamepad::GamepadControls::Axis axis) const;
    int rawAxis(Axis axis) const { return m_raw[index(axis)]; }
    Q_INVOKABLE bool button(sortie::gamepad::GamepadControls::Button button) const { return m_attached && m_buttons[index(button)]; }

    AxisShaping shaping(Axis axis) const { return m_shaping[index(axis)]; }
    // Emits axesChanged() when it changes what axis() reads.
    void setShaping(Axis axis, const AxisShaping &shaping);
    // The default until settings are bound: the whole raw range, no dead zone, no expo.
    static AxisShaping defaultShaping(Axis axis);

    // Fed by GamepadManager (or a test). A raw change is announced by flushAxes() (one
    // axesChanged() for every axis moved since the last flush); a button's change at once, unless
    // announce is false (the state read when the device is opened: a button held while the
    // gamepad is plugged in is no press).
    void setRawAxis(Axis axis, int raw);
    void flushAxes();
    void setButton(Button button, bool down, bool announce = true);
    void markDetached();

signals:
    void axesChanged();
    void buttonPressed(sortie::gamepad::GamepadControls::Button button);
    void buttonReleased(sortie::gamepad::GamepadControls::Button button);
    void detached();

private:
    static constexpr int index(Axis axis) { return int(axis); }
    static constexpr int index(Button button) { return int(button); }

    int m_instanceId;
    QString m_name;
    QString m_guid;
    bool m_attached = true;
    bool m_axesDirty = false;
    std::array<int, kAxisCount> m_raw{};
    std::array<AxisShaping, kAxisCount> m_shaping{};
    std::array<bool, kButtonCount> m_buttons{};
};

} // namespace sortie::gamepad
