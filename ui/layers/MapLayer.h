#pragma once

#include <QPointer>
#include <QQuickPaintedItem>

#include "MapView.h"
#include "MapViewport.h"

namespace sortie::ui {

// Base of the items drawn over a MapView: each draws many things with QPainter, so it also
// renders under the software scene graph. A layer fills its map (anchors.fill: map) and
// repaints when the map's viewport changes. Presses a layer does not want go on to the map.
class MapLayer : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("MapLayer is a base class")
    Q_PROPERTY(sortie::ui::MapView *map READ map WRITE setMap NOTIFY mapChanged)

public:
    explicit MapLayer(QQuickItem *parent = nullptr);

    MapView *map() const { return m_map; }
    void setMap(MapView *map);
    // The map's viewport, or a default one before a map is set.
    MapViewport viewport() const;

signals:
    void mapChanged();

protected:
    // The map moved or zoomed: by default, draw again.
    virtual void onViewportChanged();

private:
    QPointer<MapView> m_map;
};

} // namespace sortie::ui
