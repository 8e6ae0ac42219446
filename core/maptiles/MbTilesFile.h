#pragma once

#include "MbTilesMetadata.h"
#include "TileId.h"

#include <QByteArray>
#include <QList>
#include <QSet>
#include <QString>

#include <optional>

namespace sortie::maptiles {

// One MBTiles file (SQLite through Qt Sql's QSQLITE driver): the map reads it, the prefetch job
// writes it. Rows are XYZ here (TileId) and TMS in the file. Writes go in transactions, so a
// process killed mid-write leaves the file as it was before that batch (SQLite's journal rolls the
// batch back at the next open for writing).
class MbTilesFile
{
public:
    enum class Mode { ReadOnly, ReadWrite }; // ReadWrite creates the file and its tables when missing

    // Bounds on what a pack from anywhere makes one statement do (core/sqlite's openOutside).
    static constexpr qint64 kMaxRows = 10'000'000;
    static constexpr qint64 kMaxSteps = 100'000'000;  // ~2.5 s of CPU
    static constexpr int kMaxTileBytes = 16 << 20;
    static constexpr int kMaxMetadataRows = 1000;

    struct Tile
    {
        TileId id;
        QByteArray data;
    };

    MbTilesFile() = default;
    ~MbTilesFile();
    MbTilesFile(const MbTilesFile &) = delete;
    MbTilesFile &operator=(const MbTilesFile &) = delete;

    // False with an operator-readable reason naming the file when it is missing, not SQLite or
    // has no tiles table. Opened as a file from outside (core/sqlite): read-only never writes it,
    // no triggers, and each statement stopped, named, past kMaxRows rows or kMaxSteps steps.
    bool open(const QString &path, Mode mode, QString *error);
    void close();
    bool isOpen() const { return !m_connection.isEmpty(); }
    QString path() const { return m_path; }

    MbTilesMetadata metadata(QString *error = nullptr) const;
    // Replaces the metadata rows (one transaction).
    bool writeMetadata(const MbTilesMetadata &metadata, QString *error);

    // The stored bytes of a tile; nothing when the file has no such tile (or the read failed:
    // then `error` says why).
    std::optional<QByteArray> tile(const TileId &id, QString *error = nullptr) const;
    // Stores tiles, replacing any already there, all in one transaction (all or none).
    bool writeTiles(const QList<Tile> &tiles, QString *error);
    // The tiles stored between these zooms, as TileId::packed() values.
    QSet<quint64> storedTiles(int minZoom, int maxZoom, QString *error = nullptr) const;
    qint64 tileCount() const;
    // Mean size of a stored tile in bytes; nothing for a file without tiles.
    std::optional<double> meanTileBytes() const;
    // The lowest and highest zoom that hold tiles; nothing for a file without tiles.
    std::optional<std::pair<int, int>> storedZoomRange() const;
    // SQLite's own check of the file ("ok" when whole).
    QString integrityCheck() const;

private:
    QString m_path;
    QString m_connection;
};

} // namespace sortie::maptiles
