#include "MapView.h"

#include "Graticule.h"
#include "WebMercator.h"

#include <QFontMetrics>
#include <QGuiApplication>
#include <QPainter>
#include <QStyleHints>

#include <algorithm>
#include <cmath>

namespace sortie::ui {

namespace {
constexpr double kWheelZoomPerNotch = 0.5;
constexpr double kKeyPanPixels = 80.0;
constexpr int kMaxTilesOnScreen = 600;
} // namespace

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
    connect(&m_tiles, &TileManager::tilesChanged, this, [this] {
        polish();
        update();
    });
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

void MapView::setDark(bool dark)
{
    if (dark == isDark())
        return;
    m_tiles.baseMap().setDark(dark);
    emit darkChanged();
    update();
}

void MapView::setGraticuleVisible(bool visible)
{
    if (visible == m_graticule)
        return;
    m_graticule = visible;
    emit graticuleVisibleChanged();
    update();
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
    polish();
    update();
    emit viewportChanged();
}

void MapView::geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry)
{
    QQuickPaintedItem::geometryChange(newGeometry, oldGeometry);
    MapViewport next = m_viewport;
    next.setSize(newGeometry.size());
    changeViewport(next);
}

void MapView::updatePolish()
{
    const int z = m_tiles.tileZoom(m_viewport.zoom());
    const double n = std::exp2(z);
    const double tilePixels = m_viewport.scale() / n;
    const QRectF visible = m_viewport.visibleNormalised();
    const QPointF origin = m_viewport.toScreenUnwrapped(QPointF(0, 0));
    const int x0 = int(std::floor(visible.left() * n));
    const int x1 = int(std::floor(visible.right() * n));
    const int y0 = std::max(0, int(std::floor(visible.top() * n)));
    const int y1 = std::min(int(n) - 1, int(std::floor(visible.bottom() * n)));
    const QPointF middle(width() / 2, height() / 2);

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
    m_tiles.require(keys);
}

void MapView::paint(QPainter *painter)
{
    const MapPalette palette = m_tiles.baseMap().palette();
    painter->fillRect(QRectF(0, 0, width(), height()), palette.sea);
    // While the zoom stays (panning), tiles are scaled once and then only blitted.
    const bool steadyZoom = m_viewport.zoom() == m_scaledZoom;
    if (!steadyZoom) {
        m_scaledTiles.clear();
        m_scaledZoom = m_viewport.zoom();
    }
    for (const PlacedTile &tile : std::as_const(m_placed)) {
        const TileManager::Image image = m_tiles.best(tile.key);
        if (!image.image)
            continue;
        const QRect target(tile.target.topLeft(), tile.target.size() + QSize(1, 1));
        const bool exact = std::abs(target.width() - image.sourceRect.width()) < 0.5
                           && std::abs(target.height() - image.sourceRect.height()) < 0.5;
        if (exact) {
            painter->drawImage(target.topLeft(), *image.image, image.sourceRect);
        } else if (steadyZoom) {
            painter->drawImage(target.topLeft(), scaledTile(image, target.size()));
        } else {
            painter->setRenderHint(QPainter::SmoothPixmapTransform, true);
            painter->drawImage(QRectF(target), *image.image, image.sourceRect);
        }
    }
    if (m_graticule) {
        painter->setRenderHint(QPainter::Antialiasing, false);
        Graticule::paint(*painter, m_viewport, palette);
    }
}

const QImage &MapView::scaledTile(const TileManager::Image &image, QSize size)
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

void MapView::setGesture(Gesture gesture)
{
    const bool wasPanning = isPanning();
    m_gesture = gesture;
    if (wasPanning != isPanning())
        emit panningChanged();
}

void MapView::setSelectionRect(const QRectF &rect)
{
    if (rect == m_selectionRect)
        return;
    m_selectionRect = rect;
    emit selectionRectChanged();
}

void MapView::mousePressEvent(QMouseEvent *event)
{
    if (!m_interactive || event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    forceActiveFocus(Qt::MouseFocusReason);
    m_pressPos = m_lastPos = event->position();
    m_pressModifiers = event->modifiers();
    setGesture(Gesture::Pending);
    event->accept();
}

void MapView::mouseMoveEvent(QMouseEvent *event)
{
    const QPointF pos = event->position();
    setCursorPosition(pos);
    if (m_gesture == Gesture::Pending) {
        const int threshold = QGuiApplication::styleHints()->startDragDistance();
        if ((pos - m_pressPos).manhattanLength() < threshold)
            return;
        setGesture(m_pressModifiers & Qt::ShiftModifier ? Gesture::Select : Gesture::Pan);
    }
    if (m_gesture == Gesture::Pan) {
        panBy(pos.x() - m_lastPos.x(), pos.y() - m_lastPos.y());
    } else if (m_gesture == Gesture::Select) {
        setSelectionRect(QRectF(m_pressPos, pos).normalized());
    }
    m_lastPos = pos;
}

void MapView::mouseReleaseEvent(QMouseEvent *event)
{
    const Gesture gesture = m_gesture;
    setGesture(Gesture::None);
    if (gesture == Gesture::Pending) {
        emit clicked(toCoordinate(event->position()), int(m_pressModifiers));
    } else if (gesture == Gesture::Select) {
        const QRectF rect = m_selectionRect;
        setSelectionRect({});
        emit areaSelected(rect, int(m_pressModifiers));
    }
}

void MapView::mouseUngrabEvent()
{
    setGesture(Gesture::None);
    setSelectionRect({});
}

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

void MapView::wheelEvent(QWheelEvent *event)
{
    if (!m_interactive) {
        event->ignore();
        return;
    }
    const double notches = event->angleDelta().y() / 120.0;
    zoomAroundPoint(event->position(), zoomLevel() + notches * kWheelZoomPerNotch);
    event->accept();
}

void MapView::keyPressEvent(QKeyEvent *event)
{
    if (!m_interactive) {
        event->ignore();
        return;
    }
    const double step = kKeyPanPixels * (event->modifiers() & Qt::ShiftModifier ? 4 : 1);
    switch (event->key()) {
    case Qt::Key_Left: panBy(step, 0); break;
    case Qt::Key_Right: panBy(-step, 0); break;
    case Qt::Key_Up: panBy(0, step); break;
    case Qt::Key_Down: panBy(0, -step); break;
    case Qt::Key_Plus:
    case Qt::Key_Equal: zoomIn(); break;
    case Qt::Key_Minus:
    case Qt::Key_Underscore: zoomOut(); break;
    default: event->ignore(); return;
    }
    event->accept();
}

void MapView::touchEvent(QTouchEvent *event)
{
    if (!m_interactive) {
        event->ignore();
        return;
    }
    const auto &points = event->points();
    if (event->type() == QEvent::TouchEnd || event->type() == QEvent::TouchCancel || points.isEmpty()) {
        // A tap is a click, as with the mouse.
        if (m_gesture == Gesture::Pending && event->type() == QEvent::TouchEnd && !points.isEmpty())
            emit clicked(toCoordinate(points[0].position()), int(m_pressModifiers));
        setGesture(Gesture::None);
        event->accept();
        return;
    }
    if (points.size() >= 2) {
        const QPointF a = points[0].position();
        const QPointF b = points[1].position();
        const QPointF centre = (a + b) / 2.0;
        const double distance = std::max(1.0, std::hypot(a.x() - b.x(), a.y() - b.y()));
        const bool started = m_gesture != Gesture::Pinch || points[0].state() == QEventPoint::Pressed
                             || points[1].state() == QEventPoint::Pressed;
        if (started) {
            setGesture(Gesture::Pinch);
            m_pinchStartDistance = distance;
            m_pinchStartZoom = zoomLevel();
        } else {
            MapViewport next = m_viewport;
            next.panByPixels(centre - m_pinchLastCentre);
            next.zoomAround(centre, std::clamp(m_pinchStartZoom + std::log2(distance / m_pinchStartDistance),
                                               m_minZoom, m_maxZoom));
            changeViewport(next);
        }
        m_pinchLastCentre = centre;
    } else {
        const QPointF pos = points[0].position();
        if (m_gesture == Gesture::Pinch) {
            setGesture(Gesture::Pan); // one finger lifted: go on panning, never a tap
        } else if (m_gesture == Gesture::None || points[0].state() == QEventPoint::Pressed) {
            m_pressPos = pos;
            m_pressModifiers = event->modifiers();
            setGesture(Gesture::Pending);
        } else if (m_gesture == Gesture::Pending
                   && (pos - m_pressPos).manhattanLength() >= QGuiApplication::styleHints()->startDragDistance()) {
            setGesture(Gesture::Pan);
        }
        if (m_gesture == Gesture::Pan)
            panBy(pos.x() - m_lastPos.x(), pos.y() - m_lastPos.y());
        m_lastPos = pos;
    }
    event->accept();
}

} // namespace sortie::ui
