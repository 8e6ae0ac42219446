#pragma once

#include "VehicleTypes.h"

#include <QByteArray>
#include <QSqlDatabase>
#include <QString>

#include <vector>

namespace sortie::flightlog {

// The SQLite tables of a flight log (docs/flightlog.md) and the helpers both sides share.
namespace schema {

inline constexpr int kVersion = 1;
inline constexpr const char *kApplicationId = "sortie-flightlog";
inline constexpr const char *kSuffix = ".sortielog";

// Creates the tables in an empty database; false with the SQL error otherwise.
bool create(QSqlDatabase &db, QString *error);
// Opens (or creates) a SQLite file under a connection name of its own.
QSqlDatabase open(const QString &path, const QString &connection, bool readOnly, QString *error);

// The mission as the log stores it: [[lat rad, lon rad, alt m above home, speed m/s], ...]. Radians, as
// logs have always held it; MissionItem speaks degrees, so the conversion is here.
QByteArray missionToJson(const std::vector<vehicle::MissionItem> &items);
std::vector<vehicle::MissionItem> missionFromJson(const QByteArray &json, bool *ok);

} // namespace schema
} // namespace sortie::flightlog
