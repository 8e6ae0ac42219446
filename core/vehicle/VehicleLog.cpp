#include "VehicleLog.h"

Q_LOGGING_CATEGORY(lcVehicle, "sortie.vehicle", QtInfoMsg)
