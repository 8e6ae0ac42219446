#pragma once

#include <QLoggingCategory>

// sortie.flightlog: recording, reading and replaying flight logs.
Q_DECLARE_LOGGING_CATEGORY(lcFlightLog)
