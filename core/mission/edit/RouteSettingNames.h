#pragma once

#include "Route.h"

#include <QVariant>

namespace sortie::mission {

// A route setting by the name QML and scripts use for it ("name", "safeAltitude", "maxAltitude",
// "initialSpeed", "maxSpeed", "cornerRadius", "takeoffHeight", "maxHorizontalSpeed").
enum class SettingAssignment { Set, UnknownName, NotANumber };
SettingAssignment assignRouteSetting(RouteSettings &settings, const QString &name, const QVariant &value);

} // namespace sortie::mission
