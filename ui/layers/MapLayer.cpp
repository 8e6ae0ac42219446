#include "MapLayer.h"

#include "MapView.h"

namespace sortie::ui {

MapLayer::MapLayer(QQuickItem *parent)
    : QQuickPaintedItem(parent)
{
    setAntialiasing(true);
}

void MapLayer::setMap(MapView *map)
{
    if (map == m_map)
        return;
    if (m_map)
        disconnect(m_map, nullptr, this, nullptr);
    m_map = map;
    if (m_map)
        connect(m_map, &MapView::viewportChanged, this, &MapLayer::onViewportChanged);
    onViewportChanged();
    emit mapChanged();
}

MapViewport MapLayer::viewport() const
{
    if (m_map)
        return m_map->viewport();
    return MapViewport(QPointF(0.5, 0.5), 2.0, size());
}

void MapLayer::onViewportChanged()
{
    polish();
    update();
}

} // namespace sortie::ui
