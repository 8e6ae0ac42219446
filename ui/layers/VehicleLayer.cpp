#include "VehicleLayer.h"

#include "ModelCoordinates.h"
#include "Polyline.h"
#include "VehiclePalette.h"
#include "WebMercator.h"

#include <QAbstractItemModel>
#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <QScopedValueRollback>

#include <cmath>

namespace sortie::ui {

namespace {

// Positions closer than this (about half a metre at the equator) add nothing to a trail.
constexpr double kTrailStep = 1.2e-8;
// Trails are drawn this translucent over the map (170 of 255).
constexpr qreal kTrailOpacity = 170.0 / 255.0;

// A frame never zooms closer than about 400 m across (one vehicle alone, or all at one spot).
constexpr double kMinimumFrameDegrees = 0.004;

QFont labelFont()
{
    QFont font;
    font.setPixelSize(11);
    font.setBold(true);
    return font;
}

QPainterPath arrowShape()
{
    QPainterPath path;
    path.moveTo(0, -14);
    path.lineTo(9, 10);
    path.lineTo(0, 5);
    path.lineTo(-9, 10);
    path.closeSubpath();
    return path;
}

} // namespace

VehicleLayer::VehicleLayer(QQuickItem *parent)
    : MapLayer(parent)
{
    setAcceptedMouseButtons(Qt::LeftButton);
    connect(this, &VehicleLayer::modelChanged, this, &VehicleLayer::reload);
    connect(this, &MapLayer::mapChanged, this, &VehicleLayer::watchMap);
}

void VehicleLayer::watchMap()
{
    if (m_watchedMap)
        disconnect(m_watchedMap, nullptr, this, nullptr);
    m_watchedMap = map();
    if (m_watchedMap) {
        m_framed = {m_watchedMap->latitude(), m_watchedMap->longitude(), m_watchedMap->zoomLevel()};
        connect(m_watchedMap, &MapView::viewportChanged, this, &VehicleLayer::onMapMoved);
        // A map that gets its size after the vehicles came (a page shown later) frames them then.
        auto refit = [this] {
            if (m_autoFit) {
                m_fittedCount = 0;
                keepCurrentInView();
            }
        };
        connect(m_watchedMap, &QQuickItem::widthChanged, this, refit);
        connect(m_watchedMap, &QQuickItem::heightChanged, this, refit);
    }
}

// The operator (or another layer framing its own things) moved the map: autoFit stops.
void VehicleLayer::onMapMoved()
{
    if (m_movingMap || !m_autoFit || !map())
        return;
    // A resize keeps the centre and zoom; only a pan or a zoom by the operator changes them.
    if (std::abs(map()->zoomLevel() - m_framed.zoom) < 1e-9 && std::abs(map()->latitude() - m_framed.latitude) < 1e-9
        && std::abs(map()->longitude() - m_framed.longitude) < 1e-9)
        return;
    m_autoFit = false;
    emit autoFitChanged();
}

void VehicleLayer::setFollow(bool follow)
{
    if (follow == m_follow)
        return;
    m_follow = follow;
    emit followChanged();
    if (m_follow)
        centerOn(m_current);
}

void VehicleLayer::setAutoFit(bool on)
{
    if (on == m_autoFit)
        return;
    m_autoFit = on;
    m_fittedCount = 0;
    emit autoFitChanged();
    keepCurrentInView();
}

int VehicleLayer::positionedCount() const
{
    return int(std::count_if(m_vehicles.begin(), m_vehicles.end(), [](const Vehicle &v) { return !std::isnan(v.position.x()); }));
}

bool VehicleLayer::fitToMap(qreal margin)
{
    MapView *view = map();
    // A map not laid out yet (a page not shown) is framed once it has its size.
    if (!view || view->width() <= 2 * margin || view->height() <= 2 * margin)
        return false;
    double south = 90, north = -90, west = 180, east = -180;
    bool any = false;
    auto include = [&](QPointF normalised) {
        if (std::isnan(normalised.x()))
            return;
        const QGeoCoordinate c = WebMercator::unproject(normalised);
        south = std::min(south, c.latitude());
        north = std::max(north, c.latitude());
        west = std::min(west, c.longitude());
        east = std::max(east, c.longitude());
    };
    for (const Vehicle &vehicle : m_vehicles) {
        if (std::isnan(vehicle.position.x()))
            continue;
        any = true;
        include(vehicle.position);
        include(vehicle.home);
    }
    if (!any)
        return false;
    const double padLatitude = std::max(0.0, kMinimumFrameDegrees - (north - south)) / 2;
    const double padLongitude = std::max(0.0, kMinimumFrameDegrees - (east - west)) / 2;
    {
        QScopedValueRollback moving(m_movingMap, true);
        view->fitBounds(south - padLatitude, west - padLongitude, north + padLatitude, east + padLongitude, margin);
    }
    m_framed = {view->latitude(), view->longitude(), view->zoomLevel()};
    return true;
}

bool VehicleLayer::centerOn(int row)
{
    if (!map() || row < 0 || row >= count() || std::isnan(m_vehicles[size_t(row)].position.x()))
        return false;
    {
        QScopedValueRollback moving(m_movingMap, true);
        map()->setCenter(WebMercator::unproject(m_vehicles[size_t(row)].position));
    }
    m_framed = {map()->latitude(), map()->longitude(), map()->zoomLevel()};
    return true;
}

// After new positions: autoFit frames the fleet when a vehicle reports its first position;
// follow brings the current vehicle back to the middle once it leaves the middle half.
void VehicleLayer::keepCurrentInView()
{
    if (m_autoFit) {
        const int positioned = positionedCount();
        if (positioned > m_fittedCount && fitToMap())
            m_fittedCount = positioned;
    }
    if (m_follow && m_current >= 0 && m_current < count()) {
        const QPointF at = vehiclePosition(m_current);
        const QRectF middle(width() / 4, height() / 4, width() / 2, height() / 2);
        if (!at.isNull() && !middle.contains(at))
            centerOn(m_current);
    }
}

void VehicleLayer::setModel(QAbstractItemModel *model)
{
    if (model == m_model)
        return;
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = model;
    if (m_model) {
        connect(m_model, &QAbstractItemModel::dataChanged, this,
                [this](const QModelIndex &topLeft, const QModelIndex &bottomRight) {
                    reloadRows(topLeft.row(), bottomRight.row());
                });
        connect(m_model, &QAbstractItemModel::rowsInserted, this, &VehicleLayer::reload);
        connect(m_model, &QAbstractItemModel::rowsRemoved, this, &VehicleLayer::reload);
        connect(m_model, &QAbstractItemModel::rowsMoved, this, &VehicleLayer::reload);
        connect(m_model, &QAbstractItemModel::modelReset, this, &VehicleLayer::reload);
        connect(m_model, &QAbstractItemModel::layoutChanged, this, &VehicleLayer::reload);
        connect(m_model, &QObject::destroyed, this, [this] { setModel(nullptr); });
    }
    emit modelChanged();
}

void VehicleLayer::setCurrentIndex(int row)
{
    if (row == m_current)
        return;
    m_current = row;
    emit currentIndexChanged();
    if (m_follow)
        centerOn(m_current);
    polish(); // the labels are laid out again: the current one goes first
    repaint();
}

void VehicleLayer::setTrailLength(int points)
{
    points = std::max(0, points);
    if (points == m_trailLength)
        return;
    m_trailLength = points;
    for (Trail &trail : m_trails) {
        while (int(trail.points.size()) > m_trailLength) {
            trail.points.pop_front();
            ++trail.dropped;
        }
    }
    redrawTrails();
    emit trailLengthChanged();
    polish();
    repaint();
}

void VehicleLayer::setTrailsVisible(bool visible)
{
    if (visible == m_trailsVisible)
        return;
    m_trailsVisible = visible;
    redrawTrails();
    emit trailLengthChanged();
    polish();
    repaint();
}

void VehicleLayer::resolveRoles()
{
    m_roles.clear();
    if (!m_model)
        return;
    const QHash<int, QByteArray> names = m_model->roleNames();
    for (auto it = names.cbegin(); it != names.cend(); ++it)
        m_roles.insert(QString::fromUtf8(it.value()), it.key());
}

VehicleLayer::Vehicle VehicleLayer::read(int row) const
{
    Vehicle vehicle;
    const QModelIndex index = m_model->index(row, 0);
    auto value = [&](const QString &role) {
        const auto it = m_roles.constFind(role);
        return it == m_roles.cend() ? QVariant() : m_model->data(index, it.value());
    };
    auto number = [&](const QString &role, bool *ok) { return value(role).toDouble(ok); };
    vehicle.id = value(m_idRole).toString();
    if (vehicle.id.isEmpty())
        vehicle.id = QStringLiteral("#%1").arg(row);
    vehicle.label = value(m_labelRole).toString();
    bool okLat = false, okLon = false;
    const double lat = number(m_latitudeRole, &okLat);
    const double lon = number(m_longitudeRole, &okLon);
    if (okLat && okLon && std::isfinite(lat) && std::isfinite(lon))
        vehicle.position = WebMercator::project(lat, lon);
    const double homeLat = number(m_homeLatitudeRole, &okLat);
    const double homeLon = number(m_homeLongitudeRole, &okLon);
    if (okLat && okLon && std::isfinite(homeLat) && std::isfinite(homeLon))
        vehicle.home = WebMercator::project(homeLat, homeLon);
    bool okHeading = false;
    const double heading = number(m_headingRole, &okHeading);
    vehicle.heading = okHeading && std::isfinite(heading) ? heading : 0.0;
    vehicle.stale = value(m_staleRole).toBool();
    vehicle.color = vehicleColor(row);
    return vehicle;
}

void VehicleLayer::record(const Vehicle &vehicle)
{
    if (std::isnan(vehicle.position.x()) || m_trailLength == 0)
        return;
    Trail &trail = m_trails[vehicle.id];
    if (!trail.points.empty()) {
        const QPointF d = vehicle.position - trail.points.back();
        if (std::abs(d.x()) < kTrailStep && std::abs(d.y()) < kTrailStep)
            return;
    }
    trail.points.push_back(vehicle.position);
    while (int(trail.points.size()) > m_trailLength) {
        trail.points.pop_front();
        ++trail.dropped;
        // The picture still shows the cut points: redraw once they are a noticeable part.
        if (++m_cutSinceRedraw > std::max(16, m_trailLength / 16))
            redrawTrails();
    }
}

void VehicleLayer::redrawTrails()
{
    m_trailsStale = true;
    m_cutSinceRedraw = 0;
}

QColor VehicleLayer::colorOf(const Vehicle &vehicle) const
{
    return vehicle.stale ? QColor(0x90, 0x90, 0x90) : vehicle.color;
}

void VehicleLayer::onViewportChanged()
{
    redrawTrails();
    MapLayer::onViewportChanged();
}

void VehicleLayer::reload()
{
    resolveRoles();
    redrawTrails(); // rows (and so colours) may have changed
    m_vehicles.clear();
    const int rows = m_model ? m_model->rowCount() : 0;
    for (int row = 0; row < rows; ++row) {
        m_vehicles.push_back(read(row));
        record(m_vehicles.back());
    }
    emit vehiclesChanged();
    keepCurrentInView();
    polish();
    repaint();
}

void VehicleLayer::reloadRows(int first, int last)
{
    bool positioned = false;
    for (int row = std::max(0, first); row <= last && row < int(m_vehicles.size()); ++row) {
        const QColor before = colorOf(m_vehicles[size_t(row)]);
        const bool had = !std::isnan(m_vehicles[size_t(row)].position.x());
        m_vehicles[size_t(row)] = read(row);
        const bool has = !std::isnan(m_vehicles[size_t(row)].position.x());
        positioned = positioned || had != has;
        if (colorOf(m_vehicles[size_t(row)]) != before)
            redrawTrails();
        record(m_vehicles[size_t(row)]);
    }
    if (positioned)
        emit vehiclesChanged();
    keepCurrentInView();
    polish();
    repaint();
}

void VehicleLayer::clearTrails()
{
    m_trails.clear();
    redrawTrails();
    polish();
    repaint();
}

int VehicleLayer::trailPointCount(int row) const
{
    if (row < 0 || row >= count())
        return 0;
    const auto it = m_trails.constFind(m_vehicles[size_t(row)].id);
    return it == m_trails.cend() ? 0 : int(it->points.size());
}

QPointF VehicleLayer::vehiclePosition(int row) const
{
    if (row < 0 || row >= count() || std::isnan(m_vehicles[size_t(row)].position.x()))
        return {};
    return viewport().toScreen(m_vehicles[size_t(row)].position);
}

int VehicleLayer::vehicleAt(QPointF position, qreal radius) const
{
    const MapViewport view = viewport();
    int best = -1;
    double bestDistance = radius;
    for (size_t row = 0; row < m_vehicles.size(); ++row) {
        if (std::isnan(m_vehicles[row].position.x()))
            continue;
        const QPointF s = view.toScreen(m_vehicles[row].position);
        const double d = std::hypot(s.x() - position.x(), s.y() - position.y());
        if (d <= bestDistance) {
            bestDistance = d;
            best = int(row);
        }
    }
    return best;
}

void VehicleLayer::updatePolish()
{
    const MapViewport view = paintViewport();
    m_drawn.assign(m_vehicles.size(), Drawn());
    for (size_t row = 0; row < m_vehicles.size(); ++row) {
        const Vehicle &vehicle = m_vehicles[row];
        Drawn &drawn = m_drawn[row];
        drawn.hasPosition = !std::isnan(vehicle.position.x());
        if (!drawn.hasPosition)
            continue;
        drawn.position = view.toScreen(vehicle.position);
        if (!std::isnan(vehicle.home.x())) {
            drawn.hasHome = true;
            drawn.home = view.toScreenUnwrapped(nearestCopy(view.toNormalised(drawn.position), vehicle.home));
        }
    }
    layOutTrails(view);
    layOutLabels();
}

// Each label goes beside its arrow unless an earlier one is there; then it is stacked below
// the one in the way. The current vehicle's label is placed first, so it stays by its arrow.
void VehicleLayer::layOutLabels()
{
    const QFontMetricsF metrics(labelFont());
    std::vector<size_t> order;
    for (size_t row = 0; row < m_drawn.size(); ++row)
        if (m_drawn[row].hasPosition && !m_vehicles[row].label.isEmpty())
            order.push_back(row);
    std::stable_partition(order.begin(), order.end(), [this](size_t row) { return int(row) == m_current; });
    std::vector<QRectF> placed;
    for (size_t row : order) {
        Drawn &drawn = m_drawn[row];
        const QSizeF size(metrics.horizontalAdvance(m_vehicles[row].label) + 8, metrics.height() + 2);
        QRectF rect(drawn.position + QPointF(16, -10 - size.height() / 2), size);
        // The arrows nearby are not covered either (a label beside a vehicle's own arrow is fine).
        auto blocked = [&](const QRectF &r) {
            for (const QRectF &other : placed)
                if (r.intersects(other))
                    return true;
            for (size_t other = 0; other < m_drawn.size(); ++other)
                if (other != row && m_drawn[other].hasPosition
                    && r.intersects(QRectF(m_drawn[other].position - QPointF(12, 12), QSizeF(24, 24))))
                    return true;
            return false;
        };
        drawn.labelMoved = false;
        for (int tries = 0; tries < 12 && blocked(rect); ++tries) {
            rect.translate(0, size.height() + 1);
            drawn.labelMoved = true;
        }
        drawn.label = rect;
        placed.push_back(rect);
    }
}

QRectF VehicleLayer::labelRect(int row) const
{
    if (row < 0 || row >= int(m_drawn.size()) || m_drawn[size_t(row)].label.isEmpty())
        return {};
    return m_drawn[size_t(row)].label.translated(paintOrigin());
}

// Whole trails after a new layout, otherwise each trail's piece since the last layout.
void VehicleLayer::layOutTrails(const MapViewport &view)
{
    const bool whole = m_trailsStale;
    const QRectF screen = QRectF(QPointF(0, 0), view.size()).adjusted(-30, -30, 30, 30);
    std::vector<TrailPicture::Stroke> strokes;
    for (size_t row = 0; row < m_vehicles.size(); ++row) {
        const Vehicle &vehicle = m_vehicles[row];
        const auto found = m_trails.find(vehicle.id);
        if (found == m_trails.end() || !m_drawn[row].hasPosition)
            continue;
        Trail &trail = *found;
        const qint64 end = trail.dropped + qint64(trail.points.size());
        const qint64 first = whole ? trail.dropped : std::max(trail.dropped, trail.drawn - 1);
        trail.drawn = end;
        if (!m_trailsVisible || end - first < 2)
            continue;
        const QPointF anchor = view.toNormalised(m_drawn[row].position);
        const size_t n = size_t(end - first);
        std::vector<QPointF> points(n);
        std::vector<bool> inside(n);
        for (size_t i = 0; i < n; ++i) {
            points[i] = view.toScreenUnwrapped(nearestCopy(anchor, trail.points[size_t(first - trail.dropped) + i]));
            inside[i] = screen.contains(points[i]);
        }
        // Only the parts of the trail near the picture are kept for drawing.
        const QColor color = colorOf(vehicle);
        QPolygonF run;
        for (size_t i = 0; i < n; ++i) {
            const bool keep = inside[i] || (i > 0 && inside[i - 1]) || (i + 1 < n && inside[i + 1]);
            if (keep) {
                run.append(points[i]);
            } else if (!run.isEmpty()) {
                strokes.push_back({simplifyPolyline(run, 0.4), color});
                run.clear();
            }
        }
        if (run.size() > 1)
            strokes.push_back({simplifyPolyline(run, 0.4), color});
    }
    if (whole) {
        m_trailPicture.restart(std::move(strokes));
        m_trailsStale = false;
        m_cutSinceRedraw = 0;
    } else {
        for (TrailPicture::Stroke &stroke : strokes)
            m_trailPicture.add(std::move(stroke));
    }
}

void VehicleLayer::paint(QPainter *painter)
{
    painter->setRenderHint(QPainter::Antialiasing, true);
    m_trailPicture.paint(*painter, kTrailOpacity);
    static const QPainterPath arrow = arrowShape();
    QFont font = painter->font();
    font.setPixelSize(11);
    font.setBold(true);
    painter->setFont(font);
    for (size_t row = 0; row < m_drawn.size() && row < m_vehicles.size(); ++row) {
        const Drawn &drawn = m_drawn[row];
        if (!drawn.hasHome)
            continue;
        const QColor color = colorOf(m_vehicles[row]);
        painter->setPen(QPen(Qt::white, 1.5));
        painter->setBrush(color.darker(120));
        painter->drawRect(QRectF(drawn.home - QPointF(7, 7), QSizeF(14, 14)));
        painter->setPen(Qt::white);
        painter->drawText(QRectF(drawn.home - QPointF(7, 7), QSizeF(14, 14)), Qt::AlignCenter, QStringLiteral("H"));
    }
    std::vector<size_t> order;
    for (size_t row = 0; row < m_drawn.size() && row < m_vehicles.size(); ++row)
        if (m_drawn[row].hasPosition && int(row) != m_current)
            order.push_back(row);
    if (m_current >= 0 && size_t(m_current) < m_drawn.size() && m_drawn[size_t(m_current)].hasPosition)
        order.push_back(size_t(m_current)); // on top of the others
    painter->setFont(labelFont());
    for (size_t row : order) {
        const Drawn &drawn = m_drawn[row];
        const Vehicle &vehicle = m_vehicles[row];
        const QColor color = colorOf(vehicle);
        const bool current = int(row) == m_current;
        painter->save();
        painter->translate(drawn.position);
        if (current) {
            painter->setPen(QPen(QColor(0xff, 0xd6, 0x00), 3));
            painter->setBrush(QColor(0xff, 0xd6, 0x00, 60));
            painter->drawEllipse(QPointF(0, 0), 20, 20);
            painter->scale(1.2, 1.2);
        }
        painter->rotate(vehicle.heading);
        painter->setPen(QPen(Qt::white, 2.0));
        painter->setBrush(color);
        painter->drawPath(arrow);
        painter->restore();
        if (vehicle.label.isEmpty() || drawn.label.isEmpty())
            continue;
        if (drawn.labelMoved) {
            painter->setPen(QPen(color, 1));
            painter->drawLine(drawn.position, QPointF(drawn.label.left(), drawn.label.center().y()));
        }
        painter->setPen(current ? QPen(QColor(0xff, 0xd6, 0x00), 2) : QPen(color, 1));
        painter->setBrush(current ? color : QColor(255, 255, 255, 225));
        painter->drawRoundedRect(drawn.label, 3, 3);
        painter->setPen(current ? QColor(Qt::white) : color.darker(160));
        painter->drawText(drawn.label, Qt::AlignCenter, vehicle.label);
    }
}

void VehicleLayer::mousePressEvent(QMouseEvent *event)
{
    m_pressRow = vehicleAt(event->position());
    if (m_pressRow < 0) {
        event->ignore();
        return;
    }
    event->accept();
}

void VehicleLayer::mouseReleaseEvent(QMouseEvent *event)
{
    const int row = std::exchange(m_pressRow, -1);
    if (row >= 0 && row == vehicleAt(event->position())) {
        setCurrentIndex(row);
        emit vehicleClicked(row, int(event->modifiers()));
    }
}

} // namespace sortie::ui
