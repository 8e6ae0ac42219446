#pragma once

#include "GamepadControls.h"
#include "StickShaping.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>

#include <array>

class QSettings;

namespace sortie::gamepad {

class Gamepad;

// The operator's settings for one gamepad model, kept by its GUID (docs/gamepad.md, "Settings"):
// per axis a calibration (min, centre, max as measured), a dead zone and expo; per button an action
// name ("arm", "photo", "returnHome"...: words this room does not interpret; the main session maps
// them to commands). They live in the QSettings handed in, under <group>/<GUID>/ (no global
// settings object); what was never saved reads as the defaults (defaultShaping, defaultAction).
// Every change is written to the QSettings at once (it reaches the file on QSettings::sync or
// when the QSettings is destroyed) and announced by changed().
//
// Calibration: beginCalibration(pad) with the sticks at rest (their raw values are the centres),
// the operator moves each stick and trigger to its ends, finishCalibration() stores min/centre/max
// for every axis moved far enough each way (kMinCalibrationSpan) and returns those axes; the others
// keep the calibration they had.
class GamepadSettings : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QString guid READ guid CONSTANT FINAL)
    Q_PROPERTY(bool calibrating READ isCalibrating NOTIFY calibratingChanged FINAL)

public:
    // A quarter of a stick's half range: a side moved less than this was not moved to its end.
    static constexpr int kMinCalibrationSpan = 8192;

    GamepadSettings(QSettings *settings, const QString &group, const QString &guid, QObject *parent = nullptr);
    ~GamepadSettings() override;

    QString guid() const { return m_guid; }

    AxisShaping shaping(Axis axis) const { return m_shaping[int(axis)]; }
    void setShaping(Axis axis, const AxisShaping &shaping);
    Q_INVOKABLE double deadZone(sortie::gamepad::GamepadControls::Axis axis) const { return m_shaping[int(axis)].deadZone; }
    Q_INVOKABLE void setDeadZone(sortie::gamepad::GamepadControls::Axis axis, double deadZone);
    Q_INVOKABLE double expo(sortie::gamepad::GamepadControls::Axis axis) const { return m_shaping[int(axis)].expo; }
    Q_INVOKABLE void setExpo(sortie::gamepad::GamepadControls::Axis axis, double expo);
    AxisCalibration calibration(Axis axis) const { return m_shaping[int(axis)].calibration; }
    void setCalibration(Axis axis, const AxisCalibration &calibration);

    // The action name a button stands for; empty: none.
    Q_INVOKABLE QString action(sortie::gamepad::GamepadControls::Button button) const { return m_actions[int(button)]; }
    Q_INVOKABLE void setAction(sortie::gamepad::GamepadControls::Button button, const QString &action);
    // The buttons bound to an action, in the enumeration's order.
    QList<Button> buttonsFor(const QString &action) const;

    // Forgets what was saved for this GUID: the defaults again.
    Q_INVOKABLE void resetToDefaults();

    // Sticks: the whole raw range, a dead zone of 0.05, no expo; triggers 0..32767, a dead zone of
    // 0.02, no expo.
    static AxisShaping defaultShaping(Axis axis);
    // Start "arm", A "photo", B "returnHome", X "hold", Y "land", the others none (a proposal: the
    // main session asks its usual confirmation before a command such as arming).
    static QString defaultAction(Button button);

    // Applies this shaping to the gamepad now and on every change (until either is destroyed).
    void bind(Gamepad *pad);

    void beginCalibration(Gamepad *pad);
    bool isCalibrating() const { return !m_calibrationPad.isNull(); }
    QList<Axis> finishCalibration();
    void cancelCalibration();

signals:
    void changed();
    void calibratingChanged();

private:
    QString axisKey(Axis axis, const char *field) const;
    QString buttonKey(Button button) const;
    void load();
    void storeShaping(Axis axis);
    void sample();

    QSettings *m_settings;
    QString m_prefix;  // "<group>/<guid>/"
    QString m_guid;
    std::array<AxisShaping, kAxisCount> m_shaping{};
    std::array<QString, kButtonCount> m_actions{};

    QPointer<Gamepad> m_calibrationPad;
    std::array<AxisCalibration, kAxisCount> m_measured{};
    QMetaObject::Connection m_sampling;
    QMetaObject::Connection m_calibrationLost;
};

} // namespace sortie::gamepad
