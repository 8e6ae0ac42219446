#pragma once

#include <QPointer>
#include <QQuickItem>

#include <functional>

#include "MapView.h"
#include "MapViewport.h"

class QPainter;

namespace sortie::ui {

class LayerCanvas;

// Base of the items drawn over a MapView: each draws many things with QPainter, so it also
// renders under the software scene graph. A layer fills its map (anchors.fill: map). It draws
// into a picture (a LayerCanvas child) that reaches a margin beyond the map on every side:
// while the map pans by whole pixels within that margin, the picture only moves; a zoom, a
// resize or a longer pan lays it out and draws it anew for the map's new viewport. A hidden layer
// (a page not shown) keeps no picture: it is laid out and drawn again when it shows. Presses a
// layer does not want go on to the map.
class MapLayer : public QQuickItem
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("MapLayer is a base class")
    Q_PROPERTY(sortie::ui::MapView *map READ map WRITE setMap NOTIFY mapChanged)
    // A layer underneath whose labels this layer's labels keep clear of (the vehicles' and the
    // traffic's of the zones'): the moving labels give way, so the zones are not drawn again
    // whenever something moves.
    Q_PROPERTY(sortie::ui::MapLayer *labelsBelow READ labelsBelow WRITE setLabelsBelow NOTIFY labelsBelowChanged)

public:
    static constexpr int kDefaultPanMargin = 256;

    explicit MapLayer(QQuickItem *parent = nullptr);

    MapView *map() const { return m_map; }
    void setMap(MapView *map);
    // The map's viewport now (for hit testing), or a default one before a map is set.
    MapViewport viewport() const;
    // The viewport the picture is laid out for: the map's when it was last drawn anew, grown
    // by the margin on every side. Layers project what they draw with this one.
    const MapViewport &paintViewport() const { return m_paintViewport; }
    // Where paintViewport's top-left corner is in this item's coordinates now.
    QPointF paintOrigin() const;
    // How far the picture reaches beyond the map now: the pan margin, or 0 just after a zoom.
    int pictureMargin() const { return m_pictureMargin; }

    // The colours to draw with: the map's theme (MapView::colours), the light scheme's without a map.
    const MapPalette &colours() const;

    // Draws the layer in paintViewport's pixels.
    virtual void paint(QPainter *painter) = 0;
    // The labels this layer drew, in this item's coordinates (labelsPlaced() when they change).
    virtual std::vector<QRectF> placedLabels() const { return {}; }
    MapLayer *labelsBelow() const { return m_labelsBelow; }
    void setLabelsBelow(MapLayer *layer);

    // Test hooks: how often the layer asked for its picture to be drawn again, and how often it was.
    int repaintRequests() const { return m_repaintRequests; }
    int paintCount() const;

signals:
    void mapChanged();
    void labelsBelowChanged();
    void labelsPlaced();

protected:
    // What the layer shows changed: draw the picture again (for the same paintViewport). The one
    // place a layer asks for a frame: a hidden layer (a page not shown) asks for none, it is laid
    // out and drawn anew when it shows (followViewport).
    void repaint();
    // What the layer lays out changed too: polish (updatePolish), then repaint; nothing while hidden.
    void relayout();
    // The picture needs a new layout for a new paintViewport: by default, polish and draw again.
    virtual void onViewportChanged();
    // The operator's language changed: words the layer made are made again. By default, polish and
    // draw again; a layer that words its marks elsewhere re-words them here.
    virtual void onLanguageChanged() { relayout(); }
    void setPanMargin(int pixels);
    // The labels of `labelsBelow` in paintViewport's pixels, for this layer's LabelPlacer.
    std::vector<QRectF> labelsToKeepClearOf() const;
    // An extra picture that moves with the main one, drawn over it; the layer sets its geometry
    // (in paintViewport pixels) and calls update() on it.
    LayerCanvas *createOverlay(std::function<void(QPainter &)> painter);
    void geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry) override;
    void itemChange(ItemChange change, const ItemChangeData &value) override;

private:
    void followViewport();
    void dropPicture();

    QPointer<MapView> m_map;
    QPointer<MapLayer> m_labelsBelow;
    LayerCanvas *m_canvas = nullptr;
    MapViewport m_paintViewport;
    int m_margin = kDefaultPanMargin;
    int m_pictureMargin = 0;
    int m_repaintRequests = 0;
};

} // namespace sortie::ui
