#include "OrthophotoLayer.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace sortie::ui {

namespace {
constexpr int kMaxTiles = 400;
constexpr int kAncestorLevels = 4;  // how far up a stand-in tile may come from
} // namespace

OrthophotoLayer::OrthophotoLayer(QQuickItem *parent) : MapLayer(parent)
{
    connect(&m_tiles, &OrthophotoTiles::tileReady, this, [this] {
        repaint();
        emit drawn();
    });
    connect(&m_tiles, &OrthophotoTiles::fileChanged, this, [this] {
        emit fileChanged();
        polish();
        repaint();
    });
}

void OrthophotoLayer::setFile(const QString &file)
{
    m_tiles.setFile(file);
}

void OrthophotoLayer::fitToMap(qreal margin)
{
    const QRectF box = m_tiles.footprint();
    if (map() && isValid())
        map()->fitBounds(box.top(), box.left(), box.bottom(), box.right(), margin);
}

void OrthophotoLayer::updatePolish()
{
    m_placed.clear();
    if (!isValid())
        return;
    const MapViewport &viewport = paintViewport();
    const int z = std::clamp(int(std::floor(viewport.zoom() + 0.5)), 0, 22);
    const double n = std::exp2(z);
    const double tilePixels = viewport.scale() / n;
    const QRectF visible = viewport.visibleNormalised();
    const QPointF origin = viewport.toScreenUnwrapped(QPointF(0, 0));
    const int x0 = int(std::floor(visible.left() * n)), x1 = int(std::floor(visible.right() * n));
    const int y0 = std::max(0, int(std::floor(visible.top() * n))), y1 = std::min(int(n) - 1, int(std::floor(visible.bottom() * n)));
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1 && m_placed.size() < kMaxTiles; ++x) {
            const TileKey key{z, ((x % int(n)) + int(n)) % int(n), y};
            if (!m_tiles.touches(key))
                continue;
            const QPoint topLeft(int(std::lround(origin.x() + x * tilePixels)), int(std::lround(origin.y() + y * tilePixels)));
            const QPoint bottomRight(int(std::lround(origin.x() + (x + 1) * tilePixels)), int(std::lround(origin.y() + (y + 1) * tilePixels)));
            m_placed.append({key, QRect(topLeft, bottomRight)});
        }
    }
    // Nearest the middle first: what the operator looks at renders first.
    const QPointF middle(viewport.size().width() / 2, viewport.size().height() / 2);
    std::sort(m_placed.begin(), m_placed.end(), [&middle](const Placed &a, const Placed &b) {
        const QPointF da = QRectF(a.target).center() - middle, db = QRectF(b.target).center() - middle;
        return QPointF::dotProduct(da, da) < QPointF::dotProduct(db, db);
    });
    QList<TileKey> keys;
    keys.reserve(m_placed.size());
    for (const Placed &p : std::as_const(m_placed))
        keys.append(p.key);
    m_tiles.require(keys);
}

void OrthophotoLayer::paint(QPainter *painter)
{
    int drawnTiles = 0;
    painter->setRenderHint(QPainter::SmoothPixmapTransform, true);
    for (const Placed &p : std::as_const(m_placed)) {
        if (const QImage *image = m_tiles.find(p.key)) {
            ++drawnTiles;
            if (!image->isNull())
                painter->drawImage(p.target, *image);
            continue;
        }
        // Not yet rendered: the nearest cached ancestor's part, scaled up.
        TileKey up = p.key;
        for (int level = 1; level <= kAncestorLevels && up.z > 0; ++level) {
            up = up.parent();
            const QImage *image = m_tiles.find(up);
            if (!image)
                continue;
            if (!image->isNull()) {
                const int parts = 1 << level;
                const double side = 256.0 / parts;
                const QRectF source((p.key.x % parts) * side, (p.key.y % parts) * side, side, side);
                painter->drawImage(QRectF(p.target), *image, source);
            }
            break;
        }
    }
    m_drawnTiles = drawnTiles;
}

} // namespace sortie::ui
