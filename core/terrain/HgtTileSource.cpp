#include "HgtTileSource.h"

#include "TerrainLog.h"

#include <QDir>
#include <QFileInfo>

#include <cmath>
#include <QCoreApplication>

namespace sortie::terrain {

HgtTileSource::HgtTileSource(const QString &path, QObject *parent)
    : ElevationSource(parent), m_path(path)
{
    const QFileInfo info(path);
    if (info.isDir()) {
        const QDir dir(path);
        const QStringList names = dir.entryList({QStringLiteral("*.hgt"), QStringLiteral("*.HGT")}, QDir::Files | QDir::Readable);
        for (const QString &n : names) {
            if (const auto cell = parseHgtName(n))
                m_files.insert(cell->key(), dir.filePath(n));
            else
                qCWarning(lcTerrain).noquote() << dir.filePath(n) << "is not named like an SRTM tile (NxxEyyy.hgt); skipped";
        }
        return;
    }
    if (!info.exists()) {
        m_error = QCoreApplication::translate("HgtTileSource", "%1: no such file or folder").arg(path);
        return;
    }
    const auto cell = parseHgtName(info.fileName());
    if (!cell) {
        m_error = QCoreApplication::translate("HgtTileSource", "%1: not an SRTM tile name (NxxEyyy.hgt names the tile's south-west corner)").arg(path);
        return;
    }
    m_files.insert(cell->key(), path);
    if (!openAll())
        m_error = m_problems.join(QLatin1Char('\n'));
}

HgtTileSource::~HgtTileSource() = default;

QString HgtTileSource::name() const
{
    return QCoreApplication::translate("HgtTileSource", "SRTM tiles (%1)").arg(QDir::toNativeSeparators(m_path));
}

bool HgtTileSource::openAll()
{
    bool ok = true;
    for (auto it = m_files.cbegin(); it != m_files.cend(); ++it) {
        const int key = it.key();
        ok &= tileFor({key / 360 - 90, key % 360 - 180}) != nullptr;
    }
    return ok;
}

const HgtTile *HgtTileSource::tileFor(TileCell cell)
{
    const int key = cell.key();
    if (key == m_lastKey)
        return m_last;
    const HgtTile *tile = nullptr;
    if (auto found = m_loaded.find(key); found != m_loaded.end()) {
        tile = found->second.tile ? &*found->second.tile : nullptr;
    } else if (auto file = m_files.constFind(key); file != m_files.cend()) {
        Loaded loaded;
        loaded.file = std::make_unique<QFile>(*file);
        QString error;
        if (!loaded.file->open(QIODevice::ReadOnly)) {
            error = QStringLiteral("%1: %2").arg(*file, loaded.file->errorString());
        } else {
            const qint64 size = loaded.file->size();
            const uchar *data = size > 0 ? loaded.file->map(0, size) : nullptr;
            if (!data && size > 0)
                error = QCoreApplication::translate("HgtTileSource", "%1: cannot be mapped: %2").arg(*file, loaded.file->errorString());
            else
                loaded.tile = HgtTile::fromData(QByteArrayView(reinterpret_cast<const char *>(data), size), cell, *file, &error);
        }
        if (!loaded.tile) {
            qCWarning(lcTerrain).noquote() << error;
            m_problems << error;
            loaded.file.reset();  // unmaps
        }
        const Loaded &stored = m_loaded.emplace(key, std::move(loaded)).first->second;
        tile = stored.tile ? &*stored.tile : nullptr;
    }
    m_lastKey = key;
    m_last = tile;
    return tile;
}

ElevationSample HgtTileSource::sampleIn(TileCell cell, double latitude, double longitude)
{
    const HgtTile *tile = tileFor(cell);
    return tile ? tile->sample(latitude, longitude) : ElevationSample::noData();
}

ElevationSample HgtTileSource::sample(const GeoPoint &p)
{
    if (!p.isValid())
        return ElevationSample::noData();
    const TileCell cell = TileCell::containing(p.latitude, p.longitude);
    ElevationSample s = sampleIn(cell, p.latitude, p.longitude);
    if (s.hasValue())
        return s;
    // On a cell's south or west edge the neighbouring tile holds the same posts: use it when this one
    // has nothing (the tiles overlap by one row and one column).
    if (p.latitude == cell.south && cell.south > -90) {
        const ElevationSample t = sampleIn({cell.south - 1, cell.west}, p.latitude, p.longitude);
        if (t.hasValue())
            return t;
    }
    if (p.longitude == cell.west && cell.west > -180) {
        const ElevationSample t = sampleIn({cell.south, cell.west - 1}, p.latitude, p.longitude);
        if (t.hasValue())
            return t;
    }
    return s;
}

} // namespace sortie::terrain
