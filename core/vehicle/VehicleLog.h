#pragma once

#include <QLoggingCategory>

// sortie.vehicle: every command and upload sent to a vehicle and its result (CommandLog writes them),
// and vehicle links' state changes.
Q_DECLARE_LOGGING_CATEGORY(lcVehicle)
