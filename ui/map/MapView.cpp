#include "MapView.h"

#include "Graticule.h"
#include "WebMercator.h"

#include <QFontMetrics>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace sortie::ui {

MapView::MapView(QQuickItem *parent)
    : QQuickPaintedItem(parent)
    , m_viewport(QPointF(0.5, 0.5), 2.0, QSizeF())
{
    setAcceptedMouseButtons(Qt::LeftButton);
    setAcceptHoverEvents(true);
    setAcceptTouchEvents(true);
    setActiveFocusOnTab(true);
    setOpaquePainting(true);
    setFlag(ItemHasContents, true);
    connect(&m_tiles, &TileManager::tilesChanged, this, &MapView::redraw);
    connect(&m_tiles, &TileManager::statusChanged, this, &MapView::tileStatusChanged);
}

QGeoCoordinate MapView::center() const
{
    return WebMercator::unproject(m_viewport.centre());
}

void MapView::setCenter(const QGeoCoordinate &center)
{
    if (!center.isValid())
        return;
    MapViewport next = m_viewport;
    next.setCentre(WebMercator::project(center));
    changeViewport(next);
}

void MapView::setLatitude(double latitude) { setCenter(QGeoCoordinate(latitude, longitude())); }
void MapView::setLongitude(double longitude) { setCenter(QGeoCoordinate(latitude(), longitude)); }

void MapView::setZoomLevel(double zoom)
{
    MapViewport next = m_viewport;
    next.setZoom(std::clamp(zoom, m_minZoom, m_maxZoom));
    changeViewport(next);
}

void MapView::setMinimumZoomLevel(double zoom)
{
    if (zoom == m_minZoom)
        return;
    m_minZoom = std::clamp(zoom, MapViewport::kMinZoom, MapViewport::kMaxZoom);
    emit zoomRangeChanged();
    setZoomLevel(zoomLevel());
}

void MapView::setMaximumZoomLevel(double zoom)
{
    if (zoom == m_maxZoom)
        return;
    m_maxZoom = std::clamp(zoom, MapViewport::kMinZoom, MapViewport::kMaxZoom);
    emit zoomRangeChanged();
    setZoomLevel(zoomLevel());
}

void MapView::setTileSource(TileSource *source)
{
    if (source == m_tiles.source())
        return;
    m_tiles.setSource(source);
    emit tileSourceChanged();
    emit tileStatusChanged();
}

void MapView::setTheme(Theme *theme)
{
    if (theme == m_theme)
        return;
    if (m_theme)
        disconnect(m_theme, nullptr, this, nullptr);
    m_theme = theme;
    if (m_theme)
        connect(m_theme, &Theme::coloursChanged, this, &MapView::takeColours);
    emit themeChanged();
    takeColours();
}

void MapView::takeColours()
{
    const MapPalette colours = m_theme ? m_theme->mapPalette() : MapPalette::light();
    if (colours == m_colours)
        return;
    m_colours = colours;
    m_tiles.baseMap().setPalette(colours);
    emit coloursChanged();
    redraw();
}

void MapView::setGraticuleVisible(bool visible)
{
    if (visible == m_graticule)
        return;
    m_graticule = visible;
    emit graticuleVisibleChanged();
    redraw();
}

qreal MapView::labelBandTop() const
{
    return m_graticule ? Graticule::labelBands(QFontMetrics(Graticule::labelFont(QFont()))).top() : 0;
}

qreal MapView::labelBandLeft() const
{
    return m_graticule ? Graticule::labelBands(QFontMetrics(Graticule::labelFont(QFont()))).left() : 0;
}

QList<QRectF> MapView::graticuleLabelRects() const
{
    QList<QRectF> rects;
    if (!m_graticule)
        return rects;
    for (const Graticule::Label &l : Graticule::labels(m_viewport, QFontMetrics(Graticule::labelFont(QFont()))))
        rects.append(l.rect);
    return rects;
}

void MapView::setInteractive(bool interactive)
{
    if (interactive == m_interactive)
        return;
    m_interactive = interactive;
    emit interactiveChanged();
}

QString MapView::attribution() const
{
    const TileSource *source = m_tiles.source();
    if (source && source->isReachable())
        return source->attribution().isEmpty() ? source->name() : source->attribution();
    return m_tiles.baseMap().attribution();
}

QPointF MapView::fromCoordinate(const QGeoCoordinate &coordinate) const
{
    return m_viewport.geoToScreen(coordinate);
}

QGeoCoordinate MapView::toCoordinate(QPointF screen) const
{
    return m_viewport.screenToGeo(screen);
}

void MapView::panBy(qreal dx, qreal dy)
{
    MapViewport next = m_viewport;
    next.panByPixels(QPointF(dx, dy));
    changeViewport(next);
}

void MapView::zoomAroundPoint(QPointF screen, double zoom)
{
    MapViewport next = m_viewport;
    next.zoomAround(screen, std::clamp(zoom, m_minZoom, m_maxZoom));
    changeViewport(next);
}

void MapView::fitBounds(double south, double west, double north, double east, qreal margin)
{
    const QPointF a = WebMercator::project(north, west);
    QPointF b = WebMercator::project(south, east);
    if (b.x() < a.x())
        b.rx() += 1.0; // the box crosses the antimeridian
    const double w = std::max(1.0, width() - 2 * margin);
    const double h = std::max(1.0, height() - 2 * margin);
    const double spanX = std::max(b.x() - a.x(), 1e-9);
    const double spanY = std::max(b.y() - a.y(), 1e-9);
    const double zoom = std::log2(std::min(w / spanX, h / spanY) / WebMercator::kTileSize);
    MapViewport next = m_viewport;
    next.setZoom(std::clamp(zoom, m_minZoom, m_maxZoom));
    next.setCentre((a + b) / 2.0);
    changeViewport(next);
}

void MapView::setCursorPosition(QPointF screen)
{
    m_hoverPos = screen;
    const QGeoCoordinate coordinate = m_viewport.screenToGeo(screen);
    if (coordinate == m_cursor && m_cursorInside)
        return;
    m_cursor = coordinate;
    m_cursorInside = true;
    emit cursorChanged();
}

void MapView::changeViewport(const MapViewport &viewport)
{
    if (viewport == m_viewport)
        return;
    m_viewport = viewport;
    if (m_cursorInside)
        setCursorPosition(m_hoverPos);
    redraw();
    emit viewportChanged();
}

void MapView::redraw()
{
    // A hidden map (a page not shown, whose vehicles still move its viewport) would still cost the
    // window a frame for polish() and update(): it is laid out and drawn when it shows.
    if (!isVisible())
        return;
    polish();
    update();
}

void MapView::itemChange(ItemChange change, const ItemChangeData &value)
{
    QQuickPaintedItem::itemChange(change, value);
    if (change == ItemVisibleHasChanged)
        redraw();
}

void MapView::geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry)
{
    QQuickPaintedItem::geometryChange(newGeometry, oldGeometry);
    MapViewport next = m_viewport;
    next.setSize(newGeometry.size());
    changeViewport(next);
}

void MapView::setViewport(const MapViewport &viewport)
{
    MapViewport next = viewport;
    next.setSize(m_viewport.size());
    changeViewport(next);
}

void MapView::updatePolish()
{
    m_tiles.require(m_tilePainter.layOut(m_viewport, m_tiles.tileZoom(m_viewport.zoom())));
}

void MapView::paint(QPainter *painter)
{
    m_tilePainter.paint(*painter, m_viewport, m_tiles);
    if (m_graticule) {
        painter->setRenderHint(QPainter::Antialiasing, false);
        Graticule::paint(*painter, m_viewport, m_colours);
    }
}

void MapView::mousePressEvent(QMouseEvent *event) { m_gestures.mousePress(event); }
void MapView::mouseMoveEvent(QMouseEvent *event) { m_gestures.mouseMove(event); }
void MapView::mouseReleaseEvent(QMouseEvent *event) { m_gestures.mouseRelease(event); }
void MapView::mouseUngrabEvent() { m_gestures.mouseUngrab(); }
void MapView::wheelEvent(QWheelEvent *event) { m_gestures.wheel(event); }
void MapView::keyPressEvent(QKeyEvent *event) { m_gestures.keyPress(event); }
void MapView::touchEvent(QTouchEvent *event) { m_gestures.touch(event); }

void MapView::hoverMoveEvent(QHoverEvent *event)
{
    setCursorPosition(event->position());
}

void MapView::hoverLeaveEvent(QHoverEvent *)
{
    if (!m_cursorInside)
        return;
    m_cursorInside = false;
    emit cursorChanged();
}

} // namespace sortie::ui
