#include "TileManager.h"

#include "LanguageChange.h"

#include <cmath>

namespace sortie::ui {

namespace {
constexpr int kAncestorLevels = 8;
}

TileManager::TileManager(QObject *parent)
    : QObject(parent)
{
    connect(&m_baseMap, &TileSource::tileReady, this, &TileManager::baseMapTileReady);
    connect(&m_baseMap, &TileSource::invalidated, this, &TileManager::baseMapInvalidated);
    // The status line and the attribution are worded as read; the base map's are worded again first.
    i18n::onLanguageChange(this, [this] {
        m_baseMap.reword();
        emit statusChanged();
    });
}

void TileManager::setSource(TileSource *source)
{
    if (source == m_source)
        return;
    if (m_source)
        disconnect(m_source, nullptr, this, nullptr);
    m_source = source;
    m_sourceCache.clear();
    m_pending.clear();
    m_failed.clear();
    m_lastFailure.clear();
    if (m_source) {
        connect(m_source, &TileSource::tileReady, this, &TileManager::sourceTileReady);
        connect(m_source, &TileSource::tileFailed, this, &TileManager::sourceTileFailed);
        connect(m_source, &TileSource::invalidated, this, &TileManager::sourceInvalidated);
        connect(m_source, &TileSource::reachableChanged, this, &TileManager::sourceReachableChanged);
        connect(m_source, &TileSource::infoChanged, this, &TileManager::sourceInvalidated);
        connect(m_source, &QObject::destroyed, this, [this] { setSource(nullptr); });
    }
    emit tilesChanged();
    emit statusChanged();
}

int TileManager::tileZoom(double zoom) const
{
    const TileSource &range = m_source ? static_cast<const TileSource &>(*m_source) : m_baseMap;
    const int z = int(std::floor(zoom + 0.5));
    return std::clamp(z, range.minimumZoomLevel(), std::max(range.minimumZoomLevel(), range.maximumZoomLevel()));
}

bool TileManager::sourceCovers(const TileKey &key) const
{
    return m_source && key.z >= m_source->minimumZoomLevel() && key.z <= m_source->maximumZoomLevel();
}

void TileManager::require(const QList<TileKey> &visible)
{
    const int before = loadingCount();
    if (m_source) {
        for (const TileKey &key : m_source->cancelPending())
            m_pending.remove(key);
    }
    // Requests go out farthest first: sources serve the newest request first.
    for (auto it = visible.crbegin(); it != visible.crend(); ++it) {
        const TileKey &key = *it;
        const bool sourceHas = m_sourceCache.contains(key);
        if (!sourceHas && sourceCovers(key) && !m_pending.contains(key) && !m_failed.contains(key)) {
            m_pending.insert(key);
            m_source->requestTile(key);
        }
        if (!sourceHas && !m_baseMapCache.contains(key) && !m_baseMapPending.contains(key)) {
            m_baseMapPending.insert(key);
            m_baseMap.requestTile(key);
        }
    }
    if (before != loadingCount())
        emit statusChanged();
}

TileManager::Image TileManager::best(const TileKey &key) const
{
    if (const QImage *image = m_sourceCache.find(key))
        return {image, image->rect(), false};
    // A blurred real tile beats the base map while zooming in; the base map beats a very blurred one.
    auto ancestor = [&key](const TileCache &cache, int levels, bool baseMap) -> Image {
        TileKey up = key;
        for (int level = 1; level <= levels && up.z > 0; ++level) {
            up = up.parent();
            if (const QImage *image = cache.find(up)) {
                const double part = image->width() / double(1 << level);
                const double x = (key.x - (up.x << level)) * part;
                const double y = (key.y - (up.y << level)) * part;
                return {image, QRectF(x, y, part, part), baseMap};
            }
        }
        return {};
    };
    if (Image image = ancestor(m_sourceCache, 2, false); image.image)
        return image;
    if (const QImage *image = m_baseMapCache.find(key))
        return {image, image->rect(), true};
    if (Image image = ancestor(m_baseMapCache, kAncestorLevels, true); image.image)
        return image;
    return ancestor(m_sourceCache, kAncestorLevels, false);
}

QString TileManager::status() const
{
    if (!m_source)
        return tr("Offline base map");
    if (!m_source->isReachable())
        return tr("%1 — offline base map shown").arg(m_source->errorString());
    if (!m_pending.isEmpty())
        return tr("%1: loading %n tile(s)", nullptr, int(m_pending.size())).arg(m_source->name());
    if (!m_failed.isEmpty())
        return tr("%1: %n tile(s) missing — %2", nullptr, int(m_failed.size())).arg(m_source->name(), m_lastFailure);
    return m_source->name();
}

void TileManager::sourceTileReady(const TileKey &key, const QImage &image)
{
    m_pending.remove(key);
    m_failed.remove(key);
    m_sourceCache.insert(key, image);
    emit tilesChanged();
    emit statusChanged();
}

void TileManager::sourceTileFailed(const TileKey &key, const QString &message)
{
    m_pending.remove(key);
    m_failed.insert(key);
    m_lastFailure = message;
    emit statusChanged();
}

void TileManager::sourceInvalidated()
{
    m_sourceCache.clear();
    m_pending.clear();
    m_failed.clear();
    emit tilesChanged();
    emit statusChanged();
}

void TileManager::sourceReachableChanged()
{
    // A server that came back gets asked again for what it could not give.
    if (m_source && m_source->isReachable())
        m_failed.clear();
    emit tilesChanged();
    emit statusChanged();
}

void TileManager::baseMapTileReady(const TileKey &key, const QImage &image)
{
    m_baseMapPending.remove(key);
    m_baseMapCache.insert(key, image);
    emit tilesChanged();
}

void TileManager::baseMapInvalidated()
{
    m_baseMapCache.clear();
    m_baseMapPending.clear();
    emit tilesChanged();
}

} // namespace sortie::ui
