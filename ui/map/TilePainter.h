#pragma once

#include "MapViewport.h"
#include "TileKey.h"
#include "TileManager.h"

#include <QHash>
#include <QImage>
#include <QList>
#include <QRect>

class QPainter;

namespace sortie::ui {

// Lays the tiles that cover a viewport out in pixels and draws them from a TileManager over the
// sea colour. While the zoom stays (panning), each tile that does not fit its square pixel for
// pixel is scaled once and then only blitted.
class TilePainter
{
public:
    // The tiles at `tileZoom` that cover `viewport`, nearest its middle first (each key once):
    // what the manager is to have ready.
    QList<TileKey> layOut(const MapViewport &viewport, int tileZoom);
    // Draws the tiles of the last layout, and the sea wherever there is none.
    void paint(QPainter &painter, const MapViewport &viewport, const TileManager &tiles);

private:
    struct PlacedTile
    {
        TileKey key;
        QRect target;
    };
    const QImage &scaledTile(const TileManager::Image &image, QSize size);

    QList<PlacedTile> m_placed;
    QHash<QString, QImage> m_scaledTiles; // tiles resampled for m_scaledZoom
    double m_scaledZoom = -1;
};

} // namespace sortie::ui
