#include "FlightLogSchema.h"

#include "TelemetryField.h"
#include "OutsideDatabase.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSqlError>
#include <QSqlQuery>

namespace sortie::flightlog::schema {

bool create(QSqlDatabase &db, QString *error)
{
    const char *const statements[] = {
        "CREATE TABLE IF NOT EXISTS meta(key TEXT PRIMARY KEY, value TEXT NOT NULL)",
        "CREATE TABLE IF NOT EXISTS vehicles(id INTEGER PRIMARY KEY, key TEXT NOT NULL UNIQUE, name TEXT NOT NULL,"
        " protocol TEXT NOT NULL, type TEXT NOT NULL, autopilot TEXT NOT NULL)",
        // One row per vehicle and flush (about a second): the telemetry of every field, encoded by
        // TelemetryBlockCodec. Rows are appended in time order; the rowid is the order.
        "CREATE TABLE IF NOT EXISTS blocks(id INTEGER PRIMARY KEY, vehicle INTEGER NOT NULL, t0 INTEGER NOT NULL,"
        " t1 INTEGER NOT NULL, count INTEGER NOT NULL, data BLOB NOT NULL)",
        "CREATE TABLE IF NOT EXISTS events(id INTEGER PRIMARY KEY, vehicle INTEGER, time INTEGER NOT NULL,"
        " kind TEXT NOT NULL, text TEXT NOT NULL, ok INTEGER)",
        "CREATE TABLE IF NOT EXISTS missions(id INTEGER PRIMARY KEY, vehicle INTEGER NOT NULL, time INTEGER NOT NULL,"
        " items TEXT NOT NULL)",
    };
    QSqlQuery q(db);
    for (const char *sql : statements) {
        if (!q.exec(QString::fromLatin1(sql))) {
            if (error)
                *error = q.lastError().text();
            return false;
        }
    }
    q.prepare(QStringLiteral("INSERT OR IGNORE INTO meta(key, value) VALUES (?, ?)"));
    const std::pair<const char *, QString> meta[] = {
        {"application", QString::fromLatin1(kApplicationId)},
        {"version", QString::number(kVersion)},
    };
    for (const auto &[key, value] : meta) {
        q.addBindValue(QString::fromLatin1(key));
        q.addBindValue(value);
        if (!q.exec()) {
            if (error)
                *error = q.lastError().text();
            return false;
        }
    }
    return true;
}

QSqlDatabase open(const QString &path, const QString &connection, bool readOnly, QString *error)
{
    sqlite::OutsideLimits limits;
    limits.maxRows = kMaxRows;
    limits.views = false;  // every table of a log is a table: a view named events is someone else's file
    return sqlite::openOutside(path, connection, readOnly ? sqlite::Access::ReadOnly : sqlite::Access::ReadWrite, limits, error);
}

QByteArray missionToJson(const std::vector<vehicle::MissionItem> &items)
{
    QJsonArray array;
    for (const vehicle::MissionItem &item : items)
        array.append(QJsonArray{vehicle::radiansFromDegrees(item.latitude), vehicle::radiansFromDegrees(item.longitude), item.altitude, item.speed});
    return QJsonDocument(array).toJson(QJsonDocument::Compact);
}

std::vector<vehicle::MissionItem> missionFromJson(const QByteArray &json, bool *ok)
{
    std::vector<vehicle::MissionItem> items;
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    *ok = doc.isArray();
    for (const QJsonValue &v : doc.array()) {
        const QJsonArray a = v.toArray();
        if (a.size() != 4 || !a[0].isDouble() || !a[1].isDouble() || !a[2].isDouble() || !a[3].isDouble()) {
            *ok = false;
            return {};
        }
        items.push_back({vehicle::degreesFromRadians(a[0].toDouble()), vehicle::degreesFromRadians(a[1].toDouble()), a[2].toDouble(), a[3].toDouble(), 0, {}});
    }
    return items;
}

} // namespace sortie::flightlog::schema
