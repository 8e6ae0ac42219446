#pragma once

#include "TelemetryField.h"

#include <QString>

namespace sortie::ui {

// A telemetry field as the operator reads it ("Ground speed"), in the current language; the key
// ("groundSpeed", vehicle::fieldName) stays what QML and the settings store.
QString telemetryFieldTitle(vehicle::TelemetryField field);

} // namespace sortie::ui
