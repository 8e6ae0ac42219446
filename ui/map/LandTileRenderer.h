#pragma once

#include "LandOutlines.h"
#include "MapPalette.h"
#include "TileKey.h"

#include <QImage>

#include <vector>

namespace sortie::ui {

// Draws one offline base-map tile: sea, land and coastline. Pure: safe to run on any thread.
class LandTileRenderer
{
public:
    static QImage render(const LandOutlines &outlines, const TileKey &key, const MapPalette &palette,
                         int tileSize = 256);

    // Sutherland-Hodgman: the part of a closed ring inside `rect` (exposed for tests).
    static std::vector<QPointF> clipRing(const std::vector<QPointF> &ring, const QRectF &rect, double shiftX);
};

} // namespace sortie::ui
