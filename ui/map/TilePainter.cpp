#include "TilePainter.h"

#include "MapPalette.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace sortie::ui {

namespace {
constexpr int kMaxTilesOnScreen = 600;
} // namespace

QList<TileKey> TilePainter::layOut(const MapViewport &viewport, int tileZoom)
{
    const int z = tileZoom;
    const double n = std::exp2(z);
    const double tilePixels = viewport.scale() / n;
    const QRectF visible = viewport.visibleNormalised();
    const QPointF origin = viewport.toScreenUnwrapped(QPointF(0, 0));
    const int x0 = int(std::floor(visible.left() * n));
    const int x1 = int(std::floor(visible.right() * n));
    const int y0 = std::max(0, int(std::floor(visible.top() * n)));
    const int y1 = std::min(int(n) - 1, int(std::floor(visible.bottom() * n)));
    const QPointF middle(viewport.size().width() / 2, viewport.size().height() / 2);

    m_placed.clear();
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1 && m_placed.size() < kMaxTilesOnScreen; ++x) {
            const int wrapped = ((x % int(n)) + int(n)) % int(n);
            const QPoint topLeft(int(std::lround(origin.x() + x * tilePixels)), int(std::lround(origin.y() + y * tilePixels)));
            const QPoint bottomRight(int(std::lround(origin.x() + (x + 1) * tilePixels)),
                                     int(std::lround(origin.y() + (y + 1) * tilePixels)));
            m_placed.append({TileKey{z, wrapped, y}, QRect(topLeft, bottomRight - QPoint(1, 1))});
        }
    }
    std::sort(m_placed.begin(), m_placed.end(), [&middle](const PlacedTile &a, const PlacedTile &b) {
        const QPointF da = QRectF(a.target).center() - middle;
        const QPointF db = QRectF(b.target).center() - middle;
        return QPointF::dotProduct(da, da) < QPointF::dotProduct(db, db);
    });
    QList<TileKey> keys;
    keys.reserve(m_placed.size());
    for (const PlacedTile &tile : std::as_const(m_placed)) {
        if (!keys.contains(tile.key))
            keys.append(tile.key);
    }
    return keys;
}

void TilePainter::paint(QPainter &painter, const MapViewport &viewport, const TileManager &tiles)
{
    const MapPalette palette = tiles.baseMap().palette();
    painter.fillRect(QRectF(QPointF(0, 0), viewport.size()), palette.sea);
    // While the zoom stays (panning), tiles are scaled once and then only blitted.
    const bool steadyZoom = viewport.zoom() == m_scaledZoom;
    if (!steadyZoom) {
        m_scaledTiles.clear();
        m_scaledZoom = viewport.zoom();
    }
    for (const PlacedTile &tile : std::as_const(m_placed)) {
        const TileManager::Image image = tiles.best(tile.key);
        if (!image.image)
            continue;
        const QRect target(tile.target.topLeft(), tile.target.size() + QSize(1, 1));
        const bool exact = std::abs(target.width() - image.sourceRect.width()) < 0.5
                           && std::abs(target.height() - image.sourceRect.height()) < 0.5;
        if (exact) {
            painter.drawImage(target.topLeft(), *image.image, image.sourceRect);
        } else if (steadyZoom) {
            painter.drawImage(target.topLeft(), scaledTile(image, target.size()));
        } else {
            painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
            painter.drawImage(QRectF(target), *image.image, image.sourceRect);
        }
    }
}

const QImage &TilePainter::scaledTile(const TileManager::Image &image, QSize size)
{
    const QString key = QStringLiteral("%1/%2,%3,%4/%5x%6")
                            .arg(image.image->cacheKey())
                            .arg(image.sourceRect.x())
                            .arg(image.sourceRect.y())
                            .arg(image.sourceRect.width())
                            .arg(size.width())
                            .arg(size.height());
    auto it = m_scaledTiles.find(key);
    if (it == m_scaledTiles.end()) {
        if (m_scaledTiles.size() > kMaxTilesOnScreen)
            m_scaledTiles.clear();
        const QImage source = image.image->copy(image.sourceRect.toAlignedRect());
        it = m_scaledTiles.insert(key, source.scaled(size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation));
    }
    return it.value();
}

} // namespace sortie::ui
