#pragma once

#include <QSqlDatabase>
#include <QString>

namespace sortie::sqlite {

// What a file from outside may make one statement do before it is stopped.
struct OutsideLimits
{
    qint64 maxRows = 20'000'000;          // rows one statement returns (the one past it ends the statement)
    qint64 maxSteps = 200'000'000;        // SQLite virtual-machine steps one statement runs (~5 s of CPU)
    int maxValueBytes = 64 << 20;         // one string or blob (SQLITE_LIMIT_LENGTH)
    bool views = false;                   // may the file's views be read (MBTiles' tiles may be one)
};

enum class Access { ReadOnly, ReadWrite };

// Opens an SQLite file that came from outside under a connection name of its own, through QSQLITE,
// hardened before any of its schema is read: read-only unless asked (a read-only connection never
// writes the file: no journal or -wal is applied to it), SQLITE_DBCONFIG_DEFENSIVE (no
// writable_schema, no journal_mode=OFF), trusted_schema off (the schema's views and triggers call no
// function with side effects), no triggers, views only if `limits.views`, and every statement
// stopped once it has returned `maxRows` rows or run `maxSteps` steps (statementStopped() says so).
// Not open, with the reason in `error`, when SQLite cannot open it or the hardening cannot be applied.
QSqlDatabase openOutside(const QString &path, const QString &connection, Access access, const OutsideLimits &limits,
                         QString *error);

// Why SQLite stopped the connection's last statement when a bound did (empty when none did):
// "more than 20000000 rows" / "more than 1000000000 steps", for the caller's message.
QString statementStopped(const QSqlDatabase &db);

} // namespace sortie::sqlite
