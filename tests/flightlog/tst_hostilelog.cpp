// Flight logs from outside (issue 36): .sortielog files this test crafts with SQLite's own API.
// A log whose events (or blocks) are a recursive VIEW is refused at once, naming the table, in
// bounded memory and time (the view would never end, and each of its rows is a megabyte); a log
// left with its -wal beside it is read with the committed transactions, and the operator's files
// are left byte for byte as they were (no journal applied to them, no -shm made beside them).
#include "FlightLog.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <sqlite3.h>

using namespace sortie;
using flightlog::FlightLog;

namespace {

// Runs `sql` on a new SQLite file (or the one there); empty when it went through, else SQLite's message.
QString craft(const QString &path, const char *sql, bool leaveWal = false)
{
    sqlite3 *db = nullptr;
    if (sqlite3_open(path.toUtf8().constData(), &db) != SQLITE_OK)
        return QString::fromUtf8(sqlite3_errmsg(db));
    if (leaveWal)
        sqlite3_db_config(db, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr);
    char *message = nullptr;
    const int rc = sqlite3_exec(db, sql, nullptr, nullptr, &message);
    const QString why = rc == SQLITE_OK ? QString() : QString::fromUtf8(message);
    sqlite3_free(message);
    sqlite3_close(db);
    return why;
}

// The tables of a log, as FlightLogSchema makes them, with its header row; `events` left to the caller.
constexpr const char kLogWithoutEvents[] =
    "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);"
    "INSERT INTO meta VALUES ('application', 'sortie-flightlog'), ('version', '1');"
    "CREATE TABLE vehicles(id INTEGER PRIMARY KEY, key TEXT NOT NULL UNIQUE, name TEXT NOT NULL, protocol TEXT NOT NULL,"
    " type TEXT NOT NULL, autopilot TEXT NOT NULL);"
    "CREATE TABLE missions(id INTEGER PRIMARY KEY, vehicle INTEGER NOT NULL, time INTEGER NOT NULL, items TEXT NOT NULL);";
constexpr const char kBlocksTable[] =
    "CREATE TABLE blocks(id INTEGER PRIMARY KEY, vehicle INTEGER NOT NULL, t0 INTEGER NOT NULL, t1 INTEGER NOT NULL,"
    " count INTEGER NOT NULL, data BLOB NOT NULL);";
constexpr const char kEventsTable[] =
    "CREATE TABLE events(id INTEGER PRIMARY KEY, vehicle INTEGER, time INTEGER NOT NULL, kind TEXT NOT NULL, text TEXT NOT NULL, ok INTEGER);";
// Without end, a megabyte a row.
constexpr const char kRecursiveEvents[] =
    "CREATE VIEW events AS WITH RECURSIVE r(n) AS (SELECT 1 UNION ALL SELECT n + 1 FROM r)"
    " SELECT n AS id, NULL AS vehicle, n AS time, 'note' AS kind, printf('%.*c', 1000000, 'x') AS text, NULL AS ok FROM r;";
constexpr const char kRecursiveBlocks[] =
    "CREATE VIEW blocks AS WITH RECURSIVE r(n) AS (SELECT 1 UNION ALL SELECT n + 1 FROM r)"
    " SELECT n AS id, 1 AS vehicle, n AS t0, n AS t1, 1 AS count, zeroblob(1000000) AS data FROM r;";

QMap<QString, QByteArray> folderBytes(const QString &folder)
{
    QMap<QString, QByteArray> out;
    for (const QFileInfo &f : QDir(folder).entryInfoList(QDir::Files)) {
        QFile file(f.filePath());
        if (file.open(QIODevice::ReadOnly))
            out.insert(f.fileName(), QCryptographicHash::hash(file.readAll(), QCryptographicHash::Sha256));
    }
    return out;
}

} // namespace

class TestHostileLog : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }

private slots:
    void aRecursiveViewAsEventsIsRefused()
    {
        const QString log = path("view-events.sortielog");
        const QByteArray sql = QByteArray(kLogWithoutEvents) + kBlocksTable + kRecursiveEvents;
        QCOMPARE(craft(log, sql.constData()), QString());
        QString error;
        QVERIFY(!FlightLog::open(log, &error));
        QVERIFY2(error.startsWith(log) && error.contains(QLatin1String("events is a view, not a table")), qPrintable(error));
    }

    void aRecursiveViewAsBlocksIsRefused()
    {
        const QString log = path("view-blocks.sortielog");
        const QByteArray sql = QByteArray(kLogWithoutEvents) + kEventsTable + kRecursiveBlocks;
        QCOMPARE(craft(log, sql.constData()), QString());
        QString error;
        QVERIFY(!FlightLog::open(log, &error));
        QVERIFY2(error.contains(QLatin1String("blocks is a view, not a table")), qPrintable(error));
    }

    void anHonestLogStillOpens()
    {
        const QString log = path("honest.sortielog");
        const QByteArray sql = QByteArray(kLogWithoutEvents) + kBlocksTable + kEventsTable +
                               "INSERT INTO events(vehicle, time, kind, text, ok) VALUES (NULL, 1000, 'note', 'take-off', NULL);";
        QCOMPARE(craft(log, sql.constData()), QString());
        QString error;
        const auto read = FlightLog::open(log, &error);
        QVERIFY2(read, qPrintable(error));
        QCOMPARE(read->events().size(), size_t(1));
        QCOMPARE(read->events()[0].text, QStringLiteral("take-off"));
        QVERIFY2(read->damage().isEmpty(), qPrintable(read->damage()));
    }

    // As a recorder killed mid-flight leaves it: the last transactions only in the -wal.
    void aWalBesideTheLogIsReadButNeverApplied()
    {
        QTemporaryDir folder;
        const QString log = folder.filePath(QStringLiteral("killed.sortielog"));
        const QByteArray sql = QByteArray(kLogWithoutEvents) + kBlocksTable + kEventsTable;
        QCOMPARE(craft(log, sql.constData()), QString());
        QCOMPARE(craft(log, "PRAGMA journal_mode=WAL; INSERT INTO events(vehicle, time, kind, text, ok) VALUES (NULL, 2000, 'note', 'only in the wal', 1);",
                       true),
                 QString());
        QVERIFY(QFileInfo(log + QStringLiteral("-wal")).size() > 0);
        const auto before = folderBytes(folder.path());
        QString error;
        const auto read = FlightLog::open(log, &error);
        QVERIFY2(read, qPrintable(error));
        QCOMPARE(read->events().size(), size_t(1));
        QCOMPARE(read->events()[0].text, QStringLiteral("only in the wal"));
        QCOMPARE(folderBytes(folder.path()), before);  // the log, its -wal and -shm untouched, nothing added
    }
};

QTEST_GUILESS_MAIN(TestHostileLog)
#include "tst_hostilelog.moc"
