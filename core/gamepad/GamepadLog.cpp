#include "GamepadLog.h"

Q_LOGGING_CATEGORY(lcGamepad, "sortie.gamepad")
