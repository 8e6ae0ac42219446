#include "MapLayer.h"

#include "LanguageChange.h"
#include "LayerCanvas.h"
#include "MapView.h"

#include <cmath>

namespace sortie::ui {

namespace {
// A shift this close to whole pixels is drawn by moving the picture (no resampling).
constexpr double kWholePixel = 1e-3;
} // namespace

MapLayer::MapLayer(QQuickItem *parent)
    : QQuickItem(parent)
    , m_canvas(new LayerCanvas(this, [this](QPainter &painter) { paint(&painter); }))
{
    setClip(true); // the picture reaches beyond the map
    i18n::onLanguageChange(this, [this] { onLanguageChanged(); });
}

void MapLayer::setLabelsBelow(MapLayer *layer)
{
    if (layer == m_labelsBelow || layer == this)
        return;
    if (m_labelsBelow)
        disconnect(m_labelsBelow, &MapLayer::labelsPlaced, this, nullptr);
    m_labelsBelow = layer;
    if (m_labelsBelow)
        connect(m_labelsBelow, &MapLayer::labelsPlaced, this, &MapLayer::relayout);
    relayout();
    emit labelsBelowChanged();
}

std::vector<QRectF> MapLayer::labelsToKeepClearOf() const
{
    std::vector<QRectF> out;
    if (!m_labelsBelow)
        return out;
    const QPointF origin = paintOrigin();
    for (const QRectF &label : m_labelsBelow->placedLabels())
        out.push_back(mapRectFromItem(m_labelsBelow, label).translated(-origin));
    return out;
}

void MapLayer::setMap(MapView *map)
{
    if (map == m_map)
        return;
    if (m_map)
        disconnect(m_map, nullptr, this, nullptr);
    m_map = map;
    if (m_map) {
        connect(m_map, &MapView::viewportChanged, this, &MapLayer::followViewport);
        connect(m_map, &MapView::coloursChanged, this, &MapLayer::relayout);
    }
    m_paintViewport = MapViewport();
    followViewport();
    emit mapChanged();
}

const MapPalette &MapLayer::colours() const
{
    static const MapPalette light = MapPalette::light();
    return m_map ? m_map->colours() : light;
}

MapViewport MapLayer::viewport() const
{
    if (m_map)
        return m_map->viewport();
    return MapViewport(QPointF(0.5, 0.5), 2.0, size());
}

QPointF MapLayer::paintOrigin() const
{
    return m_canvas->position();
}

void MapLayer::repaint()
{
    if (!isVisible())
        return; // update() on a hidden item still costs the window a frame
    ++m_repaintRequests;
    m_canvas->update();
}

void MapLayer::relayout()
{
    if (!isVisible())
        return; // so does polish()
    polish();
    repaint();
}

int MapLayer::paintCount() const
{
    return m_canvas->paintCount();
}

void MapLayer::onViewportChanged()
{
    relayout();
}

void MapLayer::setPanMargin(int pixels)
{
    pixels = std::max(0, pixels);
    if (pixels == m_margin)
        return;
    m_margin = pixels;
    m_paintViewport = MapViewport();
    followViewport();
}

LayerCanvas *MapLayer::createOverlay(std::function<void(QPainter &)> painter)
{
    return new LayerCanvas(m_canvas, std::move(painter));
}

void MapLayer::geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry)
{
    QQuickItem::geometryChange(newGeometry, oldGeometry);
    if (newGeometry.size() != oldGeometry.size())
        followViewport();
}

void MapLayer::itemChange(ItemChange change, const ItemChangeData &value)
{
    QQuickItem::itemChange(change, value);
    if (change == ItemVisibleHasChanged)
        followViewport();
}

void MapLayer::dropPicture()
{
    // A picture is the map's size and a margin on every side (9 MB at 1280x800): one per layer
    // of a page not shown would add up for nothing.
    m_paintViewport = MapViewport();
    m_canvas->setSize(QSizeF());
}

void MapLayer::followViewport()
{
    if (!isVisible())
        return dropPicture();
    const MapViewport view = viewport();
    const bool sameZoom = view.zoom() == m_paintViewport.zoom();
    const QSizeF grown = view.size() + QSizeF(2.0 * m_pictureMargin, 2.0 * m_pictureMargin);
    if (sameZoom && grown == m_paintViewport.size()) {
        // How far the picture's content has to move: the centres' distance in pixels.
        QPointF delta = m_paintViewport.centre() - view.centre();
        delta.rx() -= std::round(delta.x()); // across the antimeridian
        const QPointF shift = delta * view.scale();
        const QPointF whole(std::round(shift.x()), std::round(shift.y()));
        if (std::abs(shift.x() - whole.x()) < kWholePixel && std::abs(shift.y() - whole.y()) < kWholePixel
            && std::abs(whole.x()) <= m_pictureMargin && std::abs(whole.y()) <= m_pictureMargin) {
            m_canvas->setPosition(whole - QPointF(m_pictureMargin, m_pictureMargin));
            return;
        }
    }
    // While the zoom changes (a pinch, a wheel) every frame is laid out anew anyway: no margin
    // to draw until the map pans at one zoom.
    m_pictureMargin = sameZoom ? m_margin : 0;
    const double m = m_pictureMargin;
    m_paintViewport = MapViewport(view.centre(), view.zoom(), view.size() + QSizeF(2 * m, 2 * m));
    m_canvas->setPosition(QPointF(-m, -m));
    m_canvas->setSize(m_paintViewport.size());
    onViewportChanged();
}

} // namespace sortie::ui
