#include "OfflineTileSource.h"

#include "LandTileRenderer.h"

#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcTiles)

namespace sortie::ui {

OfflineTileSource::OfflineTileSource(QObject *parent)
    : TileSource(parent)
{
    setInfo(tr("Offline base map"), tr("Land outlines: Natural Earth"), 0, 20);
    m_pool.setMaxThreadCount(2);
    QString error;
    if (auto outlines = LandOutlines::fromResource(&error)) {
        m_outlines = std::make_shared<const LandOutlines>(std::move(*outlines));
    } else {
        // Sea and graticule still draw: the map is never blank.
        qCWarning(lcTiles) << "offline base map without land:" << error;
        m_outlines = std::make_shared<const LandOutlines>();
        setReachable(false, tr("The built-in land outlines could not be read: %1").arg(error));
    }
}

void OfflineTileSource::reword()
{
    setInfo(tr("Offline base map"), tr("Land outlines: Natural Earth"), minimumZoomLevel(), maximumZoomLevel());
}

OfflineTileSource::~OfflineTileSource()
{
    m_pool.clear();
    m_pool.waitForDone();
}

void OfflineTileSource::setPalette(const MapPalette &palette)
{
    if (palette.sea == m_palette.sea && palette.land == m_palette.land && palette.coast == m_palette.coast)
        return; // the tiles hold these three only
    m_palette = palette;
    ++m_generation;
    m_pool.clear();
    m_inFlight.clear();
    emit paletteChanged();
    emit invalidated();
}

void OfflineTileSource::requestTile(const TileKey &key)
{
    if (m_inFlight.contains(key))
        return;
    m_inFlight.insert(key);
    const quint64 generation = m_generation;
    const MapPalette palette = m_palette;
    std::shared_ptr<const LandOutlines> outlines = m_outlines;
    m_pool.start([this, generation, palette, outlines, key] {
        const QImage image = LandTileRenderer::render(*outlines, key, palette);
        QMetaObject::invokeMethod(this, [this, generation, key, image] { deliver(generation, key, image); },
                                  Qt::QueuedConnection);
    });
}

QList<TileKey> OfflineTileSource::cancelPending()
{
    // Rendering is cheap enough to let started tiles finish; they land in the cache.
    return {};
}

void OfflineTileSource::deliver(quint64 generation, const TileKey &key, const QImage &image)
{
    if (generation != m_generation)
        return;
    m_inFlight.remove(key);
    emit tileReady(key, image);
}

} // namespace sortie::ui
