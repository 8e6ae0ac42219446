#pragma once

#include "WaypointAction.h"

#include <QVariantMap>

#include <optional>

namespace sortie::mission {

// Actions as QVariantMaps for QML: {"kind": "wait", "seconds": 5}, {"kind": "cameraSeriesByDistance",
// "intervalMeters": 20, "shots": 0, "startDelaySeconds": 0}, ... Keys are the C++ field names.
QVariantMap actionToVariant(const WaypointAction &action);
// nullopt for an unknown kind; missing keys take the action's defaults. Opaque actions cannot be
// created from QML.
std::optional<WaypointAction> actionFromVariant(const QVariantMap &map);

} // namespace sortie::mission
