#include "LandTileRenderer.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace sortie::ui {

namespace {

enum class Edge { Left, Right, Top, Bottom };

bool inside(QPointF p, Edge edge, const QRectF &r)
{
    switch (edge) {
    case Edge::Left: return p.x() >= r.left();
    case Edge::Right: return p.x() <= r.right();
    case Edge::Top: return p.y() >= r.top();
    case Edge::Bottom: return p.y() <= r.bottom();
    }
    return false;
}

QPointF intersect(QPointF a, QPointF b, Edge edge, const QRectF &r)
{
    if (edge == Edge::Left || edge == Edge::Right) {
        const double x = edge == Edge::Left ? r.left() : r.right();
        const double t = (x - a.x()) / (b.x() - a.x());
        return {x, a.y() + t * (b.y() - a.y())};
    }
    const double y = edge == Edge::Top ? r.top() : r.bottom();
    const double t = (y - a.y()) / (b.y() - a.y());
    return {a.x() + t * (b.x() - a.x()), y};
}

void clipEdge(const std::vector<QPointF> &in, std::vector<QPointF> &out, Edge edge, const QRectF &r)
{
    out.clear();
    if (in.empty())
        return;
    QPointF prev = in.back();
    bool prevInside = inside(prev, edge, r);
    for (const QPointF &cur : in) {
        const bool curInside = inside(cur, edge, r);
        if (curInside) {
            if (!prevInside)
                out.push_back(intersect(prev, cur, edge, r));
            out.push_back(cur);
        } else if (prevInside) {
            out.push_back(intersect(prev, cur, edge, r));
        }
        prev = cur;
        prevInside = curInside;
    }
}

} // namespace

std::vector<QPointF> LandTileRenderer::clipRing(const std::vector<QPointF> &ring, const QRectF &rect, double shiftX)
{
    std::vector<QPointF> a;
    a.reserve(ring.size());
    for (const QPointF &p : ring)
        a.emplace_back(p.x() + shiftX, p.y());
    std::vector<QPointF> b;
    b.reserve(ring.size());
    clipEdge(a, b, Edge::Left, rect);
    clipEdge(b, a, Edge::Right, rect);
    clipEdge(a, b, Edge::Top, rect);
    clipEdge(b, a, Edge::Bottom, rect);
    return a;
}

QImage LandTileRenderer::render(const LandOutlines &outlines, const TileKey &key, const MapPalette &palette, int tileSize)
{
    QImage image(tileSize, tileSize, QImage::Format_ARGB32_Premultiplied);
    image.fill(palette.sea);
    const double tiles = std::exp2(key.z);
    const double span = 1.0 / tiles;
    const QRectF tileRect(key.x * span, key.y * span, span, span);
    // Clip a little outside the tile so the cut edges (which would be stroked) stay off it.
    const double margin = 3.0 * span / tileSize;
    const QRectF clipRect = tileRect.adjusted(-margin, -margin, margin, margin);
    const double scale = tiles * tileSize;

    QPainterPath path;
    path.setFillRule(Qt::OddEvenFill);
    for (const LandOutlines::Polygon &polygon : outlines.polygons()) {
        for (double shift : {-1.0, 0.0, 1.0}) {
            if (!polygon.bounds.translated(shift, 0).intersects(clipRect))
                continue;
            for (const std::vector<QPointF> &ring : polygon.rings) {
                const std::vector<QPointF> clipped = clipRing(ring, clipRect, shift);
                if (clipped.size() < 3)
                    continue;
                QPolygonF pixels;
                pixels.reserve(qsizetype(clipped.size()));
                for (const QPointF &p : clipped)
                    pixels.append((p - tileRect.topLeft()) * scale);
                path.addPolygon(pixels);
                path.closeSubpath();
            }
        }
    }
    if (path.isEmpty())
        return image;
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setBrush(palette.land);
    painter.setPen(QPen(palette.coast, key.z < 4 ? 0.8 : 1.2));
    painter.drawPath(path);
    return image;
}

} // namespace sortie::ui
