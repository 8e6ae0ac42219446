#pragma once

#include "MapGestures.h"
#include "MapPalette.h"
#include "Theme.h"
#include "MapViewport.h"
#include "TileManager.h"
#include "TilePainter.h"

#include <QGeoCoordinate>
#include <QPointer>
#include <QQuickPaintedItem>

namespace sortie::ui {

// The map: Web Mercator tiles from a TileSource over the built-in offline base map, with a
// graticule. The item holds the viewport (where the map looks, MapViewport) and the cursor
// readout; TilePainter lays out and draws the tiles, Graticule the grid, and MapGestures turns
// the operator's hands into pans, zooms, clicks and Shift+drag selections. Layers (RouteLayer,
// VehicleLayer, ...) are separate items that follow `viewportChanged`.
class MapView : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(double latitude READ latitude WRITE setLatitude NOTIFY viewportChanged)
    Q_PROPERTY(double longitude READ longitude WRITE setLongitude NOTIFY viewportChanged)
    Q_PROPERTY(QGeoCoordinate center READ center WRITE setCenter NOTIFY viewportChanged)
    Q_PROPERTY(double zoomLevel READ zoomLevel WRITE setZoomLevel NOTIFY viewportChanged)
    Q_PROPERTY(double minimumZoomLevel READ minimumZoomLevel WRITE setMinimumZoomLevel NOTIFY zoomRangeChanged)
    Q_PROPERTY(double maximumZoomLevel READ maximumZoomLevel WRITE setMaximumZoomLevel NOTIFY zoomRangeChanged)
    Q_PROPERTY(double metersPerPixel READ metersPerPixel NOTIFY viewportChanged)
    Q_PROPERTY(sortie::ui::TileSource *tileSource READ tileSource WRITE setTileSource NOTIFY tileSourceChanged)
    // The colours of the base map, the grid and every layer on it (null: the light scheme's).
    Q_PROPERTY(sortie::ui::Theme *theme READ theme WRITE setTheme NOTIFY themeChanged)
    Q_PROPERTY(bool graticuleVisible READ isGraticuleVisible WRITE setGraticuleVisible NOTIFY graticuleVisibleChanged)
    // The bands along the top and left edges where the graticule's labels go (0 when it is hidden):
    // map controls laid out clear of them never cover a label.
    Q_PROPERTY(qreal labelBandTop READ labelBandTop NOTIFY graticuleVisibleChanged)
    Q_PROPERTY(qreal labelBandLeft READ labelBandLeft NOTIFY graticuleVisibleChanged)
    Q_PROPERTY(bool interactive READ isInteractive WRITE setInteractive NOTIFY interactiveChanged)
    Q_PROPERTY(QGeoCoordinate cursorCoordinate READ cursorCoordinate NOTIFY cursorChanged)
    Q_PROPERTY(bool cursorInside READ isCursorInside NOTIFY cursorChanged)
    Q_PROPERTY(QString tileStatus READ tileStatus NOTIFY tileStatusChanged)
    Q_PROPERTY(QString attribution READ attribution NOTIFY tileStatusChanged)
    Q_PROPERTY(bool panning READ isPanning NOTIFY panningChanged)
    Q_PROPERTY(QRectF selectionRect READ selectionRect NOTIFY selectionRectChanged)

public:
    explicit MapView(QQuickItem *parent = nullptr);

    const MapViewport &viewport() const { return m_viewport; }

    double latitude() const { return center().latitude(); }
    void setLatitude(double latitude);
    double longitude() const { return center().longitude(); }
    void setLongitude(double longitude);
    QGeoCoordinate center() const;
    void setCenter(const QGeoCoordinate &center);
    double zoomLevel() const { return m_viewport.zoom(); }
    void setZoomLevel(double zoom);
    double minimumZoomLevel() const { return m_minZoom; }
    void setMinimumZoomLevel(double zoom);
    double maximumZoomLevel() const { return m_maxZoom; }
    void setMaximumZoomLevel(double zoom);
    double metersPerPixel() const { return m_viewport.metersPerPixel(); }
    TileSource *tileSource() const { return m_tiles.source(); }
    void setTileSource(TileSource *source);
    Theme *theme() const { return m_theme; }
    void setTheme(Theme *theme);
    // What the map and its layers paint with: the theme's MapPalette.
    const MapPalette &colours() const { return m_colours; }
    bool isGraticuleVisible() const { return m_graticule; }
    void setGraticuleVisible(bool visible);
    qreal labelBandTop() const;
    qreal labelBandLeft() const;
    // Where the graticule's labels are now, in item pixels (for layout checks).
    Q_INVOKABLE QList<QRectF> graticuleLabelRects() const;
    bool isInteractive() const { return m_interactive; }
    void setInteractive(bool interactive);
    QGeoCoordinate cursorCoordinate() const { return m_cursor; }
    bool isCursorInside() const { return m_cursorInside; }
    QString tileStatus() const { return m_tiles.status(); }
    QString attribution() const;
    bool isPanning() const { return m_gestures.isPanning(); }
    QRectF selectionRect() const { return m_gestures.selectionRect(); }

    Q_INVOKABLE QPointF fromCoordinate(const QGeoCoordinate &coordinate) const;
    Q_INVOKABLE QGeoCoordinate toCoordinate(QPointF screen) const;
    Q_INVOKABLE void panBy(qreal dx, qreal dy);
    Q_INVOKABLE void zoomIn() { zoomAroundPoint(QPointF(width() / 2, height() / 2), zoomLevel() + 1); }
    Q_INVOKABLE void zoomOut() { zoomAroundPoint(QPointF(width() / 2, height() / 2), zoomLevel() - 1); }
    Q_INVOKABLE void zoomAroundPoint(QPointF screen, double zoom);
    // Shows the box south..north, west..east with `margin` pixels to spare.
    Q_INVOKABLE void fitBounds(double south, double west, double north, double east, qreal margin = 40);
    // Layers that hold the mouse keep the cursor readout current through this.
    void setCursorPosition(QPointF screen);
    // Moves the map to `viewport` (its size stays the item's): for gestures that pan and zoom at once.
    void setViewport(const MapViewport &viewport);

    void paint(QPainter *painter) override;

signals:
    void viewportChanged();
    void zoomRangeChanged();
    void tileSourceChanged();
    void themeChanged();
    // The theme's colours changed (another scheme): layers draw again.
    void coloursChanged();
    void graticuleVisibleChanged();
    void interactiveChanged();
    void cursorChanged();
    void tileStatusChanged();
    void panningChanged();
    void selectionRectChanged();
    // A press and release without a drag; `modifiers` is Qt::KeyboardModifiers as an int.
    void clicked(const QGeoCoordinate &coordinate, int modifiers);
    // Shift+drag finished: the rectangle in item pixels.
    void areaSelected(const QRectF &rect, int modifiers);

protected:
    void geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry) override;
    void itemChange(ItemChange change, const ItemChangeData &value) override;
    void updatePolish() override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseUngrabEvent() override;
    void hoverMoveEvent(QHoverEvent *event) override;
    void hoverLeaveEvent(QHoverEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void touchEvent(QTouchEvent *event) override;

private:
    void changeViewport(const MapViewport &viewport);
    void redraw(); // lay out and draw again, while shown
    void takeColours();

    MapViewport m_viewport;
    QPointer<Theme> m_theme;
    MapPalette m_colours = MapPalette::light();
    TileManager m_tiles;
    TilePainter m_tilePainter;
    MapGestures m_gestures{*this};
    double m_minZoom = 1.0;
    double m_maxZoom = 20.0;
    bool m_graticule = true;
    bool m_interactive = true;
    QGeoCoordinate m_cursor;
    bool m_cursorInside = false;
    QPointF m_hoverPos;
};

} // namespace sortie::ui
