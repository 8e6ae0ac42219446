#pragma once

#include "LandOutlines.h"
#include "MapPalette.h"
#include "TileSource.h"

#include <QSet>
#include <QThreadPool>

#include <memory>

namespace sortie::ui {

// The built-in base map: Natural Earth land outlines drawn into tiles on worker threads. It
// needs no network and no file, so the map never shows an empty screen.
class OfflineTileSource : public TileSource
{
    Q_OBJECT
    QML_ELEMENT

public:
    explicit OfflineTileSource(QObject *parent = nullptr);
    ~OfflineTileSource() override;

    // The map's colours (the theme's MapPalette): tiles drawn in another palette are drawn again.
    void setPalette(const MapPalette &palette);
    // Its name and attribution in the current language (TileManager calls it on a language change).
    void reword();
    MapPalette palette() const { return m_palette; }

    void requestTile(const TileKey &key) override;
    QList<TileKey> cancelPending() override;

signals:
    void paletteChanged();

private:
    void deliver(quint64 generation, const TileKey &key, const QImage &image);

    std::shared_ptr<const LandOutlines> m_outlines;
    MapPalette m_palette = MapPalette::light();
    quint64 m_generation = 0; // results from an older palette are dropped
    QSet<TileKey> m_inFlight;
    QThreadPool m_pool;
};

} // namespace sortie::ui
