#include "GamepadControls.h"

#include <QMetaEnum>

namespace sortie::gamepad {

QString axisName(Axis axis)
{
    return QString::fromLatin1(QMetaEnum::fromType<Axis>().valueToKey(int(axis)));
}

QString buttonName(Button button)
{
    return QString::fromLatin1(QMetaEnum::fromType<Button>().valueToKey(int(button)));
}

std::optional<Axis> axisFromName(const QString &name)
{
    bool ok = false;
    const int value = QMetaEnum::fromType<Axis>().keyToValue(name.toLatin1().constData(), &ok);
    return ok ? std::optional<Axis>(Axis(value)) : std::nullopt;
}

std::optional<Button> buttonFromName(const QString &name)
{
    bool ok = false;
    const int value = QMetaEnum::fromType<Button>().keyToValue(name.toLatin1().constData(), &ok);
    return ok ? std::optional<Button>(Button(value)) : std::nullopt;
}

} // namespace sortie::gamepad
