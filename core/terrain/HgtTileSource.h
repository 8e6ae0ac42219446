#pragma once

#include "ElevationSource.h"
#include "HgtTile.h"

#include <QFile>
#include <QHash>
#include <QStringList>

#include <memory>
#include <optional>
#include <unordered_map>

namespace sortie::terrain {

// SRTM tiles from disk: one NxxEyyy.hgt file or a folder of them. The folder is listed once; a tile
// is opened, memory-mapped (QFile::map) and checked the first time a point falls in it. A tile that
// is missing gives NoData; one that is corrupt gives NoData too, and its error (naming the file)
// is kept in problems() and logged once: a bad file is never half-used.
class HgtTileSource : public ElevationSource
{
    Q_OBJECT

public:
    explicit HgtTileSource(const QString &path, QObject *parent = nullptr);
    ~HgtTileSource() override;

    QString name() const override;
    ElevationSample sample(const GeoPoint &point) override;

    QString path() const { return m_path; }
    // False with an error when the path is neither a .hgt tile nor a folder.
    bool isUsable() const { return m_error.isEmpty(); }
    QString error() const { return m_error; }
    int tileCount() const { return int(m_files.size()); }
    // Opens every tile now (a single-file source does so at once); false when one is corrupt.
    bool openAll();
    QStringList problems() const override { return m_problems; }

private:
    struct Loaded
    {
        std::unique_ptr<QFile> file;
        std::optional<HgtTile> tile;  // empty: the file was rejected
    };
    const HgtTile *tileFor(TileCell cell);
    ElevationSample sampleIn(TileCell cell, double latitude, double longitude);

    QString m_path;
    QString m_error;
    QHash<int, QString> m_files;  // cell key -> file path
    std::unordered_map<int, Loaded> m_loaded;  // stable addresses: m_last points into it
    QStringList m_problems;
    int m_lastKey = -1;
    const HgtTile *m_last = nullptr;
};

} // namespace sortie::terrain
