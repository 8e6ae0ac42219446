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
// Rows one statement of the reader takes from a log (a block is about a second of a vehicle's
// telemetry: 20 million are ~230 days of one vehicle), and the tables a log is made of.
inline constexpr qint64 kMaxRows = 20'000'000;
inline constexpr const char *kTables[] = {"meta", "vehicles", "blocks", "events", "missions"};

// Creates the tables in an empty database; false with the SQL error otherwise.
bool create(QSqlDatabase &db, QString *error);
// Opens (or creates) a SQLite file under a connection name of its own, hardened as a file from
// outside (core/sqlite): no views, no triggers, defensive; read-only never writes the file.
QSqlDatabase open(const QString &path, const QString &connection, bool readOnly, QString *error);

// The mission as the log stores it: [[lat rad, lon rad, alt m above home, speed m/s], ...]. Radians, as
// logs have always held it; MissionItem speaks degrees, so the conversion is here.
QByteArray missionToJson(const std::vector<vehicle::MissionItem> &items);
std::vector<vehicle::MissionItem> missionFromJson(const QByteArray &json, bool *ok);

} // namespace schema
} // namespace sortie::flightlog
