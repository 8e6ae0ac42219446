#pragma once

#include "FlightLog.h"

#include <QJsonObject>
#include <QString>

namespace sortie::flightlog {

// What `sortie-log info` prints: the file, its span, each vehicle with its fields and sample
// counts, the routes uploaded, the events, and where reading stopped if the log is damaged.
QJsonObject logInfoJson(const FlightLog &log);
QString logInfoText(const FlightLog &log);

} // namespace sortie::flightlog
