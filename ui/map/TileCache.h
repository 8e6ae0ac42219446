#pragma once

#include "TileKey.h"

#include <QCache>
#include <QImage>

namespace sortie::ui {

// Decoded tiles kept in memory, least recently used dropped first, bounded in bytes.
class TileCache
{
public:
    explicit TileCache(qsizetype maxMegabytes) : m_cache(maxMegabytes * 1024) {}

    void insert(const TileKey &key, const QImage &image)
    {
        m_cache.insert(key.packed(), new QImage(image), std::max<qsizetype>(1, image.sizeInBytes() / 1024));
    }
    const QImage *find(const TileKey &key) const { return m_cache.object(key.packed()); }
    bool contains(const TileKey &key) const { return m_cache.contains(key.packed()); }
    void clear() { m_cache.clear(); }
    qsizetype count() const { return m_cache.count(); }

private:
    QCache<quint64, QImage> m_cache;
};

} // namespace sortie::ui
