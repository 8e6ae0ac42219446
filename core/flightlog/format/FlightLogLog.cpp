#include "FlightLogLog.h"

Q_LOGGING_CATEGORY(lcFlightLog, "sortie.flightlog", QtInfoMsg)
