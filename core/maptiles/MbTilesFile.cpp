#include "MbTilesFile.h"

#include "OutsideDatabase.h"
#include "PrivateFiles.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QUuid>

namespace sortie::maptiles {

namespace {

void setError(QString *error, const QString &text)
{
    if (error)
        *error = text;
}

// The tables the MBTiles specification names, with its unique index so a tile is stored once.
const char *const kSchema[] = {
    "CREATE TABLE IF NOT EXISTS metadata (name TEXT, value TEXT)",
    "CREATE UNIQUE INDEX IF NOT EXISTS metadata_name ON metadata (name)",
    "CREATE TABLE IF NOT EXISTS tiles (zoom_level INTEGER, tile_column INTEGER, tile_row INTEGER, tile_data BLOB)",
    "CREATE UNIQUE INDEX IF NOT EXISTS tile_index ON tiles (zoom_level, tile_column, tile_row)",
};
// A pack from anywhere: its tiles may be a view (the specification allows one over deduplicated
// images), so views are read, and each statement is bounded (core/sqlite): a recursive view as
// `tiles` is stopped, named, instead of running forever.
sqlite::OutsideLimits outsideLimits()
{
    sqlite::OutsideLimits limits;
    limits.views = true;
    limits.maxRows = MbTilesFile::kMaxRows;
    limits.maxSteps = MbTilesFile::kMaxSteps;
    limits.maxValueBytes = MbTilesFile::kMaxTileBytes;
    return limits;
}

// SQLite's reason, or the bound that stopped the statement.
QString reasonOf(const QSqlQuery &query, const QString &connection)
{
    const QString bound = sqlite::statementStopped(QSqlDatabase::database(connection, false));
    return bound.isEmpty() ? query.lastError().text() : QCoreApplication::translate("MbTilesFile", "stopped: %1").arg(bound);
}
} // namespace

MbTilesFile::~MbTilesFile()
{
    close();
}

bool MbTilesFile::open(const QString &path, Mode mode, QString *error)
{
    close();
    if (path.isEmpty()) {
        setError(error, QCoreApplication::translate("MbTilesFile", "No MBTiles file is set."));
        return false;
    }
    if (mode == Mode::ReadOnly && !QFileInfo(path).isFile()) {
        setError(error, QCoreApplication::translate("MbTilesFile", "The MBTiles file %1 does not exist.").arg(path));
        return false;
    }
    if (mode == Mode::ReadWrite) {
        // A pack is the operator's: a new folder 0700, a new file 0600 (SQLite keeps the mode).
        QString why;
        if (!files::makePrivatePath(QFileInfo(path).absolutePath(), &why) || !files::createPrivateFile(path, &why)) {
            setError(error, QCoreApplication::translate("MbTilesFile", "Cannot open the MBTiles file %1: %2").arg(path, why));
            return false;
        }
    }
    const QString name = QStringLiteral("sortie-mbtiles-") + QUuid::createUuid().toString(QUuid::WithoutBraces);
    QString problem;
    {
        QString why;
        QSqlDatabase db = sqlite::openOutside(path, name, mode == Mode::ReadOnly ? sqlite::Access::ReadOnly : sqlite::Access::ReadWrite,
                                              outsideLimits(), &why);
        if (!db.isOpen()) {
            problem = QCoreApplication::translate("MbTilesFile", "Cannot open the MBTiles file %1: %2").arg(path, why);
        } else {
            QSqlQuery query(db);
            if (mode == Mode::ReadWrite) {
                for (const char *statement : kSchema) {
                    if (!query.exec(QString::fromLatin1(statement))) {
                        problem = QCoreApplication::translate("MbTilesFile", "%1 is not an MBTiles file Sortie can write: %2").arg(path, query.lastError().text());
                        break;
                    }
                }
            }
            if (problem.isEmpty() && !query.exec(QStringLiteral("SELECT zoom_level, tile_column, tile_row, tile_data FROM tiles LIMIT 1")))
                problem = QCoreApplication::translate("MbTilesFile", "%1 is not an MBTiles file (it has no tiles table).").arg(path);
        }
        if (!problem.isEmpty())
            db.close();
    }
    if (!problem.isEmpty()) {
        QSqlDatabase::removeDatabase(name);
        setError(error, problem);
        return false;
    }
    m_connection = name;
    m_path = path;
    return true;
}

void MbTilesFile::close()
{
    if (m_connection.isEmpty())
        return;
    {
        QSqlDatabase db = QSqlDatabase::database(m_connection, false);
        db.close();
    }
    QSqlDatabase::removeDatabase(m_connection);
    m_connection.clear();
    m_path.clear();
}

MbTilesMetadata MbTilesFile::metadata(QString *error) const
{
    QList<QPair<QString, QString>> pairs;
    QSqlQuery query(QSqlDatabase::database(m_connection, false));
    if (!query.exec(QStringLiteral("SELECT name, value FROM metadata"))) {
        setError(error, QCoreApplication::translate("MbTilesFile", "The MBTiles file %1 has no readable metadata: %2").arg(m_path, reasonOf(query, m_connection)));
        return {};
    }
    while (query.next()) {
        if (pairs.size() == kMaxMetadataRows) {  // a few keys in a real pack; a view could yield any number
            setError(error, QCoreApplication::translate("MbTilesFile", "The MBTiles file %1 has more than %2 metadata rows.").arg(m_path).arg(kMaxMetadataRows));
            return {};
        }
        pairs.append({query.value(0).toString(), query.value(1).toString()});
    }
    if (query.lastError().isValid()) {
        setError(error, QCoreApplication::translate("MbTilesFile", "The MBTiles file %1 has no readable metadata: %2").arg(m_path, reasonOf(query, m_connection)));
        return {};
    }
    return MbTilesMetadata::fromPairs(pairs);
}

bool MbTilesFile::writeMetadata(const MbTilesMetadata &metadata, QString *error)
{
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    if (!db.transaction()) {
        setError(error, QCoreApplication::translate("MbTilesFile", "Cannot write to the MBTiles file %1: %2").arg(m_path, db.lastError().text()));
        return false;
    }
    QSqlQuery query(db);
    bool ok = query.exec(QStringLiteral("DELETE FROM metadata"));
    ok = ok && query.prepare(QStringLiteral("INSERT OR REPLACE INTO metadata (name, value) VALUES (?, ?)"));
    for (const auto &[key, value] : metadata.toPairs()) {
        if (!ok)
            break;
        query.addBindValue(key);
        query.addBindValue(value);
        ok = query.exec();
    }
    if (!ok || !db.commit()) {
        setError(error, QCoreApplication::translate("MbTilesFile", "Cannot write the metadata of %1: %2").arg(m_path, query.lastError().text()));
        db.rollback();
        return false;
    }
    return true;
}

std::optional<QByteArray> MbTilesFile::tile(const TileId &id, QString *error) const
{
    QSqlQuery query(QSqlDatabase::database(m_connection, false));
    query.prepare(QStringLiteral("SELECT tile_data FROM tiles WHERE zoom_level = ? AND tile_column = ? AND tile_row = ?"));
    query.addBindValue(id.z);
    query.addBindValue(id.x);
    query.addBindValue(id.tmsRow());
    if (!query.exec()) {
        setError(error, QCoreApplication::translate("MbTilesFile", "Reading tile %1 failed: %2").arg(id.toString(), reasonOf(query, m_connection)));
        return std::nullopt;
    }
    if (!query.next())
        return std::nullopt;
    return query.value(0).toByteArray();
}

bool MbTilesFile::writeTiles(const QList<Tile> &tiles, QString *error)
{
    if (tiles.isEmpty())
        return true;
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    if (!db.transaction()) {
        setError(error, QCoreApplication::translate("MbTilesFile", "Cannot write to the MBTiles file %1: %2").arg(m_path, db.lastError().text()));
        return false;
    }
    QSqlQuery query(db);
    bool ok = query.prepare(QStringLiteral("INSERT OR REPLACE INTO tiles (zoom_level, tile_column, tile_row, tile_data) VALUES (?, ?, ?, ?)"));
    for (const Tile &tile : tiles) {
        if (!ok)
            break;
        query.addBindValue(tile.id.z);
        query.addBindValue(tile.id.x);
        query.addBindValue(tile.id.tmsRow());
        query.addBindValue(tile.data);
        ok = query.exec();
    }
    if (!ok || !db.commit()) {
        setError(error, QCoreApplication::translate("MbTilesFile", "Writing %1 tiles to %2 failed: %3").arg(tiles.size()).arg(m_path, query.lastError().text()));
        db.rollback();
        return false;
    }
    return true;
}

QSet<quint64> MbTilesFile::storedTiles(int minZoom, int maxZoom, QString *error) const
{
    QSet<quint64> stored;
    QSqlQuery query(QSqlDatabase::database(m_connection, false));
    query.setForwardOnly(true);
    query.prepare(QStringLiteral("SELECT zoom_level, tile_column, tile_row FROM tiles WHERE zoom_level BETWEEN ? AND ?"));
    query.addBindValue(minZoom);
    query.addBindValue(maxZoom);
    if (!query.exec()) {
        setError(error, QCoreApplication::translate("MbTilesFile", "Reading the tiles of %1 failed: %2").arg(m_path, reasonOf(query, m_connection)));
        return stored;
    }
    while (query.next()) {
        const int z = query.value(0).toInt();
        if (z < 0 || z > 30)
            continue;
        const TileId id{z, query.value(1).toInt(), (1 << z) - 1 - query.value(2).toInt()};
        if (id.isValid())
            stored.insert(id.packed());
    }
    if (query.lastError().isValid())
        setError(error, QCoreApplication::translate("MbTilesFile", "Reading the tiles of %1 failed: %2").arg(m_path, reasonOf(query, m_connection)));
    return stored;
}

qint64 MbTilesFile::tileCount() const
{
    QSqlQuery query(QSqlDatabase::database(m_connection, false));
    if (query.exec(QStringLiteral("SELECT COUNT(*) FROM tiles")) && query.next())
        return query.value(0).toLongLong();
    return 0;
}

std::optional<double> MbTilesFile::meanTileBytes() const
{
    QSqlQuery query(QSqlDatabase::database(m_connection, false));
    if (query.exec(QStringLiteral("SELECT AVG(LENGTH(tile_data)) FROM tiles")) && query.next() && !query.value(0).isNull())
        return query.value(0).toDouble();
    return std::nullopt;
}

std::optional<std::pair<int, int>> MbTilesFile::storedZoomRange() const
{
    QSqlQuery query(QSqlDatabase::database(m_connection, false));
    if (query.exec(QStringLiteral("SELECT MIN(zoom_level), MAX(zoom_level) FROM tiles")) && query.next() && !query.value(0).isNull())
        return std::pair{query.value(0).toInt(), query.value(1).toInt()};
    return std::nullopt;
}

QString MbTilesFile::integrityCheck() const
{
    QSqlQuery query(QSqlDatabase::database(m_connection, false));
    if (!query.exec(QStringLiteral("PRAGMA integrity_check")) || !query.next())
        return query.lastError().text();
    return query.value(0).toString();
}

} // namespace sortie::maptiles
