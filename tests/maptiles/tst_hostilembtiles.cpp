// MBTiles packs from anywhere (issue 36): files this test crafts with SQLite's own API. The
// specification lets `tiles` be a view, so a pack's views are read, but a recursive one that never
// ends is stopped by core/sqlite's bounds and named: past the step bound when it yields nothing
// (a missing tile), past the row bound when it yields rows without end (the stored-tile list); a
// metadata view of endless megabyte rows stops at the metadata bound. An honest view still serves
// its tiles, and a pack opened read-only is left byte for byte as it was. core/sqlite's row bound is
// shown on its own too.
#include "MbTilesFile.h"
#include "OutsideDatabase.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QtTest>

#include <sqlite3.h>

using namespace sortie::maptiles;

namespace {

QString craft(const QString &path, const char *sql)
{
    sqlite3 *db = nullptr;
    if (sqlite3_open(path.toUtf8().constData(), &db) != SQLITE_OK)
        return QString::fromUtf8(sqlite3_errmsg(db));
    char *message = nullptr;
    const int rc = sqlite3_exec(db, sql, nullptr, nullptr, &message);
    const QString why = rc == SQLITE_OK ? QString() : QString::fromUtf8(message);
    sqlite3_free(message);
    sqlite3_close(db);
    return why;
}

QByteArray bytesOf(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256) : QByteArray();
}

// Rows 0, 2, 4, … of zoom 1, column 0, without end: TMS row 0 is a real tile, row 1 is never
// yielded (and SQLite cannot tell that from the view: it has to run it).
constexpr const char kEndlessTiles[] =
    "CREATE TABLE metadata(name TEXT, value TEXT); INSERT INTO metadata VALUES ('name', 'endless'), ('format', 'png');"
    "CREATE VIEW tiles AS WITH RECURSIVE r(n) AS (SELECT 0 UNION ALL SELECT n + 1 FROM r)"
    " SELECT 1 AS zoom_level, 0 AS tile_column, 2 * n AS tile_row, x'89504e470d0a1a0a' AS tile_data FROM r;";

} // namespace

class TestHostileMbTiles : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void anEndlessViewAsTilesIsStoppedAndNamed()
    {
        const QString path = m_dir.filePath(QStringLiteral("endless.mbtiles"));
        QCOMPARE(craft(path, kEndlessTiles), QString());
        const QByteArray before = bytesOf(path);
        MbTilesFile pack;
        QString error;
        QVERIFY2(pack.open(path, MbTilesFile::Mode::ReadOnly, &error), qPrintable(error));
        // The one real tile: the view's first row (XYZ 1/0/1 is TMS row 0).
        const auto tile = pack.tile({1, 0, 1}, &error);
        QVERIFY2(tile, qPrintable(error));
        QVERIFY(tile->startsWith("\x89PNG"));
        // A tile the view never yields: stopped by the step bound, named.
        error.clear();
        QVERIFY(!pack.tile({1, 0, 0}, &error));
        QVERIFY2(error.contains(QStringLiteral("stopped: more than %1 steps").arg(MbTilesFile::kMaxSteps)), qPrintable(error));
        // Rows without end: stopped by a bound (here the steps come before the 10 million rows), named.
        error.clear();
        const QSet<quint64> stored = pack.storedTiles(1, 1, &error);
        QVERIFY2(error.contains(QStringLiteral("stopped: more than ")), qPrintable(error));
        QCOMPARE(stored.size(), qsizetype(1));  // of rows 0, 2, 4, … only 0 is a row of zoom 1
        QCOMPARE(pack.tileCount(), qint64(0));  // the count stopped: none claimed
        pack.close();
        QCOMPARE(bytesOf(path), before);
        QCOMPARE(QDir(m_dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("endless.mbtiles")});
    }

    // core/sqlite's row bound on its own: a statement gets its rows up to the bound (and the one past
    // it), then an error.
    void theRowBoundStopsAStatementAndSaysSo()
    {
        const QString path = m_dir.filePath(QStringLiteral("endless-rows.mbtiles"));
        QCOMPARE(craft(path, kEndlessTiles), QString());
        sortie::sqlite::OutsideLimits limits;
        limits.views = true;
        limits.maxRows = 1000;
        QString error;
        {
            QSqlDatabase db = sortie::sqlite::openOutside(path, QStringLiteral("rows"), sortie::sqlite::Access::ReadOnly, limits, &error);
            QVERIFY2(db.isOpen(), qPrintable(error));
            QSqlQuery query(db);
            query.setForwardOnly(true);
            QVERIFY(query.exec(QStringLiteral("SELECT tile_row FROM tiles")));
            int rows = 0;
            while (query.next())
                ++rows;
            QCOMPARE(rows, 1001);  // the row past the bound is the one that stops the statement
            QVERIFY(query.lastError().isValid());
            QCOMPARE(sortie::sqlite::statementStopped(db), QStringLiteral("more than 1000 rows"));
            // The next statement starts afresh.
            QVERIFY(query.exec(QStringLiteral("SELECT value FROM metadata WHERE name = 'name'")) && query.next());
            QCOMPARE(query.value(0).toString(), QStringLiteral("endless"));
            QCOMPARE(sortie::sqlite::statementStopped(db), QString());
            // Nothing is written through a read-only connection, whatever is asked.
            QVERIFY(!query.exec(QStringLiteral("CREATE TABLE x(y)")));
            query.finish();
        }
        QSqlDatabase::removeDatabase(QStringLiteral("rows"));
    }

    void endlessMetadataStopsAtItsBound()
    {
        const QString path = m_dir.filePath(QStringLiteral("endless-metadata.mbtiles"));
        QCOMPARE(craft(path, "CREATE TABLE tiles (zoom_level INTEGER, tile_column INTEGER, tile_row INTEGER, tile_data BLOB);"
                             "CREATE VIEW metadata AS WITH RECURSIVE r(n) AS (SELECT 0 UNION ALL SELECT n + 1 FROM r)"
                             " SELECT 'key' || n AS name, printf('%.*c', 100000, 'x') AS value FROM r;"),
                 QString());
        MbTilesFile pack;
        QString error;
        QVERIFY2(pack.open(path, MbTilesFile::Mode::ReadOnly, &error), qPrintable(error));
        pack.metadata(&error);
        QVERIFY2(error.contains(QStringLiteral("more than %1 metadata rows").arg(MbTilesFile::kMaxMetadataRows)), qPrintable(error));
    }

    void anHonestViewStillServesItsTiles()
    {
        // mbutil's layout: images stored once, a map from places to them, and tiles a view joining the two.
        const QString path = m_dir.filePath(QStringLiteral("deduplicated.mbtiles"));
        QCOMPARE(craft(path, "CREATE TABLE metadata(name TEXT, value TEXT); INSERT INTO metadata VALUES ('name', 'dedup'), ('format', 'png');"
                             "CREATE TABLE images(tile_id TEXT, tile_data BLOB);"
                             "CREATE TABLE map(zoom_level INTEGER, tile_column INTEGER, tile_row INTEGER, tile_id TEXT);"
                             "INSERT INTO images VALUES ('sea', x'89504e470d0a1a0a01');"
                             "INSERT INTO map VALUES (1, 0, 0, 'sea'), (1, 1, 0, 'sea'), (1, 0, 1, 'sea');"
                             "CREATE VIEW tiles AS SELECT map.zoom_level AS zoom_level, map.tile_column AS tile_column,"
                             " map.tile_row AS tile_row, images.tile_data AS tile_data FROM map JOIN images ON images.tile_id = map.tile_id;"),
                 QString());
        MbTilesFile pack;
        QString error;
        QVERIFY2(pack.open(path, MbTilesFile::Mode::ReadOnly, &error), qPrintable(error));
        QCOMPARE(pack.tileCount(), qint64(3));
        QCOMPARE(pack.storedTiles(0, 5, &error).size(), qsizetype(3));
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(pack.tile({1, 0, 1}, &error).value_or(QByteArray()), QByteArray("\x89PNG\r\n\x1a\n\x01", 9));  // TMS row 0
        QCOMPARE(pack.metadata(&error).toPairs().isEmpty(), false);
    }
};

QTEST_GUILESS_MAIN(TestHostileMbTiles)
#include "tst_hostilembtiles.moc"
