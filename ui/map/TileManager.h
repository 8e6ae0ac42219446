#pragma once

#include "OfflineTileSource.h"
#include "TileCache.h"

#include <QPointer>
#include <QRectF>
#include <QSet>

namespace sortie::ui {

// Decides which image to draw for each tile on screen. Tiles come from the chosen source
// (web or MBTiles); wherever it has nothing (yet, or at all) the offline base map stands in,
// and while a tile loads a scaled-up ancestor fills its place.
class TileManager : public QObject
{
    Q_OBJECT

public:
    struct Image
    {
        const QImage *image = nullptr;
        QRectF sourceRect;     // the part of `image` that covers the tile
        bool fromBaseMap = false;
    };

    explicit TileManager(QObject *parent = nullptr);

    TileSource *source() const { return m_source; }
    void setSource(TileSource *source);
    OfflineTileSource &baseMap() { return m_baseMap; }
    const OfflineTileSource &baseMap() const { return m_baseMap; }

    // The zoom at which tiles are fetched for a view at `zoom`.
    int tileZoom(double zoom) const;
    // The tiles on screen now, nearest the centre first: requests what is missing.
    void require(const QList<TileKey> &visible);
    Image best(const TileKey &key) const;

    int loadingCount() const { return int(m_pending.size()); }
    int failedCount() const { return int(m_failed.size()); }
    // One line for the status bar: what the map shows and why.
    QString status() const;

signals:
    void tilesChanged();
    void statusChanged();

private:
    void sourceTileReady(const TileKey &key, const QImage &image);
    void sourceTileFailed(const TileKey &key, const QString &message);
    void sourceInvalidated();
    void sourceReachableChanged();
    void baseMapTileReady(const TileKey &key, const QImage &image);
    void baseMapInvalidated();
    bool sourceCovers(const TileKey &key) const;

    QPointer<TileSource> m_source;
    OfflineTileSource m_baseMap;
    TileCache m_sourceCache{96};
    TileCache m_baseMapCache{48};
    QSet<TileKey> m_pending;
    QSet<TileKey> m_failed;
    QSet<TileKey> m_baseMapPending;
    QString m_lastFailure;
};

} // namespace sortie::ui
