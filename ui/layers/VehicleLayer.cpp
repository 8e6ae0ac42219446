#include "VehicleLayer.h"

#include "ModelCoordinates.h"
#include "Polyline.h"
#include "WebMercator.h"

#include <QAbstractItemModel>
#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace sortie::ui {

namespace {

// Positions closer than this (about half a metre at the equator) add nothing to a trail.
constexpr double kTrailStep = 1.2e-8;
// Trails are drawn this translucent over the map (170 of 255).
constexpr qreal kTrailOpacity = 170.0 / 255.0;

QColor vehicleColor(int row)
{
    static constexpr QRgb kColors[] = {0xd81b60, 0x8e24aa, 0x00897b, 0xf4511e, 0x3949ab,
                                       0x7cb342, 0x6d4c41, 0x00acc1, 0xc0ca33, 0x5e35b1};
    return QColor::fromRgb(kColors[row % int(std::size(kColors))]);
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
    polish();
    repaint();
}

void VehicleLayer::reloadRows(int first, int last)
{
    for (int row = std::max(0, first); row <= last && row < int(m_vehicles.size()); ++row) {
        const QColor before = colorOf(m_vehicles[size_t(row)]);
        m_vehicles[size_t(row)] = read(row);
        if (colorOf(m_vehicles[size_t(row)]) != before)
            redrawTrails();
        record(m_vehicles[size_t(row)]);
    }
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
    for (size_t row = 0; row < m_drawn.size() && row < m_vehicles.size(); ++row) {
        const Drawn &drawn = m_drawn[row];
        if (!drawn.hasPosition)
            continue;
        const Vehicle &vehicle = m_vehicles[row];
        const QColor color = colorOf(vehicle);
        painter->save();
        painter->translate(drawn.position);
        if (int(row) == m_current) {
            painter->setPen(QPen(QColor(0xff, 0xd6, 0x00), 3));
            painter->setBrush(Qt::NoBrush);
            painter->drawEllipse(QPointF(0, 0), 19, 19);
        }
        painter->rotate(vehicle.heading);
        painter->setPen(QPen(Qt::white, 2.0));
        painter->setBrush(color);
        painter->drawPath(arrow);
        painter->restore();
        if (!vehicle.label.isEmpty()) {
            const QPointF at = drawn.position + QPointF(16, -10);
            painter->setPen(QColor(255, 255, 255, 220));
            painter->drawText(at + QPointF(1, 1), vehicle.label);
            painter->setPen(color.darker(160));
            painter->drawText(at, vehicle.label);
        }
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
