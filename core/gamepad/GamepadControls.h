#pragma once

#include <QObject>
#include <QString>

#include <optional>

// Our own names for a gamepad's axes and buttons (SDL_GameController's, mapped in GamepadManager.cpp:
// nothing above this room sees SDL's). In a Qt namespace so QML and the settings' keys read them by
// name ("LeftX", "Start").
namespace sortie::gamepad::GamepadControls {
Q_NAMESPACE

// SDL's convention: X grows to the right, Y grows downwards (pushing a stick forward reads -1); a
// trigger reads 0 released and +1 pulled.
enum class Axis { LeftX, LeftY, RightX, RightY, TriggerLeft, TriggerRight };
Q_ENUM_NS(Axis)

enum class Button {
    A, B, X, Y,
    Back, Guide, Start,
    LeftStick, RightStick,
    LeftShoulder, RightShoulder,
    DpadUp, DpadDown, DpadLeft, DpadRight,
    Misc, Paddle1, Paddle2, Paddle3, Paddle4, Touchpad
};
Q_ENUM_NS(Button)

} // namespace sortie::gamepad::GamepadControls

namespace sortie::gamepad {
using GamepadControls::Axis;
using GamepadControls::Button;

inline constexpr int kAxisCount = 6;
inline constexpr int kButtonCount = 21;

constexpr bool isTrigger(Axis axis) { return axis == Axis::TriggerLeft || axis == Axis::TriggerRight; }

// "LeftX", "Start": the enumerators' names, as the settings store them.
QString axisName(Axis axis);
QString buttonName(Button button);
std::optional<Axis> axisFromName(const QString &name);
std::optional<Button> buttonFromName(const QString &name);

} // namespace sortie::gamepad
