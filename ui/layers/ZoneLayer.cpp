#include "ZoneLayer.h"

#include "Airspace.h"
#include "Geodesy.h"
#include "LabelPlacer.h"
#include "ZoneColours.h"

#include <QFontMetricsF>
#include <QGuiApplication>
#include <QHoverEvent>
#include <QPainter>
#include <QRegularExpression>
#include <QTimeZone>

#include <cmath>

namespace sortie::ui {

using airspace::Airspace;
using airspace::Zone;

namespace {
constexpr int kCircleSteps = 72;   // a circle drawn as a polygon of this many geodesic points
constexpr double kLabelPadding = 3;
constexpr double kHatchedSize = 12;   // pixels: a smaller zone is not hatched
constexpr double kLabelledSize = 12;  // pixels: a smaller zone gets no label unless it is the chosen one

std::vector<QGeoCoordinate> circleRing(const mission::GeoPoint &centre, double radius)
{
    std::vector<QGeoCoordinate> ring;
    ring.reserve(kCircleSteps);
    for (int i = 0; i < kCircleSteps; ++i) {
        const mission::GeoPoint p = mission::geodesicDirect(centre, 360.0 * i / kCircleSteps, radius).point;
        ring.emplace_back(p.latitude, p.longitude);
    }
    return ring;
}

// The area centroid of a ring in degrees (a flat approximation: zones are small), else its mean.
QGeoCoordinate centroid(const std::vector<mission::GeoPoint> &ring)
{
    double a = 0, cx = 0, cy = 0, mx = 0, my = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const mission::GeoPoint &p = ring[i], &q = ring[(i + 1) % ring.size()];
        const double cross = p.longitude * q.latitude - q.longitude * p.latitude;
        a += cross;
        cx += (p.longitude + q.longitude) * cross;
        cy += (p.latitude + q.latitude) * cross;
        mx += p.longitude;
        my += p.latitude;
    }
    if (std::abs(a) < 1e-12)
        return ring.empty() ? QGeoCoordinate() : QGeoCoordinate(my / double(ring.size()), mx / double(ring.size()));
    return QGeoCoordinate(cy / (3 * a), cx / (3 * a));
}

QString labelText(const Zone &z)
{
    return QStringLiteral("%1\n%2 – %3").arg(z.name, airspace::limitText(z.floor, false), airspace::limitText(z.ceiling, true));
}

QFont labelFont(const QFont &base, bool bold)
{
    QFont f = base;
    f.setBold(bold);
    return f;
}
} // namespace

ZoneLayer::ZoneLayer(QQuickItem *parent)
    : MapLayer(parent)
{
    // Only drawn: clicks go on to the map. Hover is the map's (it shows the cursor's position);
    // the layer follows the map's cursor rather than taking hover events from it.
    setAcceptedMouseButtons(Qt::NoButton);
    connect(this, &MapLayer::mapChanged, this, [this] {
        disconnect(m_cursorConnection);
        if (map())
            m_cursorConnection = connect(map(), &MapView::cursorChanged, this, &ZoneLayer::followCursor);
    });
}

void ZoneLayer::followCursor()
{
    // No tooltip while a button is held: a popup opening mid-drag would take the drag from the
    // layer that has it (a zone's corner, a waypoint).
    if (!map() || !map()->isCursorInside() || QGuiApplication::mouseButtons() != Qt::NoButton) {
        hoverAt(QPointF(-1e9, -1e9));
        return;
    }
    hoverAt(mapFromItem(map(), map()->fromCoordinate(map()->cursorCoordinate())));
}

void ZoneLayer::setAirspace(airspace::Airspace *airspace)
{
    if (airspace == m_airspace)
        return;
    if (m_airspace)
        disconnect(m_airspace, nullptr, this, nullptr);
    m_airspace = airspace;
    if (m_airspace) {
        connect(m_airspace, &Airspace::changed, this, &ZoneLayer::readZones);
        connect(m_airspace, &Airspace::selectedZoneChanged, this, &ZoneLayer::repaint);
        // Each check may move the flight's window (a new planned start): which zones apply to it.
        connect(m_airspace, &Airspace::crossingsChanged, this, &ZoneLayer::repaint);
    }
    readZones();
    emit airspaceChanged();
}

// The store learns where the map looks, so the server is asked for the zones there.
void ZoneLayer::onViewportChanged()
{
    MapLayer::onViewportChanged();
    if (!m_airspace || !isVisible() || !map())
        return;
    const MapViewport view = viewport();
    if (view.size().isEmpty())
        return;
    const QGeoCoordinate northWest = view.screenToGeo(QPointF(0, 0));
    const QGeoCoordinate southEast = view.screenToGeo(QPointF(view.size().width(), view.size().height()));
    m_airspace->lookAt(southEast.latitude(), northWest.longitude(), northWest.latitude(), southEast.longitude());
}

void ZoneLayer::readZones()
{
    m_outlines.clear();
    const int count = m_airspace ? m_airspace->count() : 0;
    for (int row = 0; row < count; ++row) {
        const Zone &z = m_airspace->zoneAt(row);
        Outline o;
        if (const auto *polygons = std::get_if<airspace::ZonePolygons>(&z.shape)) {
            for (const airspace::ZonePolygon &part : polygons->parts)
                for (size_t r = 0; r < part.rings.size(); ++r) {
                    std::vector<QGeoCoordinate> ring;
                    for (const mission::GeoPoint &p : part.rings[r])
                        ring.emplace_back(p.latitude, p.longitude);
                    o.rings.push_back(std::move(ring));
                    o.hole.push_back(r > 0);
                }
            if (!polygons->parts.empty() && !polygons->parts.front().rings.empty())
                o.centre = centroid(polygons->parts.front().rings.front());
        } else if (const auto *circle = std::get_if<airspace::ZoneCircle>(&z.shape)) {
            o.rings.push_back(circleRing(circle->center, circle->radius));
            o.hole.push_back(false);
            o.centre = QGeoCoordinate(circle->center.latitude, circle->center.longitude);
        } else if (const auto *cone = std::get_if<airspace::ZoneConeFrustum>(&z.shape)) {
            // Its widest circle is the zone's shadow on the map.
            o.rings.push_back(circleRing(cone->center, std::max(cone->bottomRadius, cone->topRadius)));
            o.hole.push_back(false);
            o.centre = QGeoCoordinate(cone->center.latitude, cone->center.longitude);
        }
        double west = 180, east = -180, south = 90, north = -90;
        for (const auto &ring : o.rings)
            for (const QGeoCoordinate &c : ring) {
                west = std::min(west, c.longitude());
                east = std::max(east, c.longitude());
                south = std::min(south, c.latitude());
                north = std::max(north, c.latitude());
            }
        o.box = west <= east ? QRectF(QPointF(west, south), QPointF(east, north)) : QRectF();
        m_outlines.push_back(std::move(o));
    }
    repaint();
}

QPainterPath ZoneLayer::pathOf(const Outline &outline, const MapViewport &view, QPointF offset) const
{
    QPainterPath path;
    path.setFillRule(Qt::OddEvenFill);
    for (const auto &ring : outline.rings) {
        QPolygonF polygon;
        polygon.reserve(qsizetype(ring.size()) + 1);
        // Corners closer than half a pixel to the last one kept add nothing but work (a 72-point
        // circle a few pixels wide, a detailed coastline zoomed out).
        for (const QGeoCoordinate &c : ring) {
            const QPointF point = view.geoToScreen(c) + offset;
            if (polygon.isEmpty() || std::abs(point.x() - polygon.last().x()) + std::abs(point.y() - polygon.last().y()) >= 0.5)
                polygon << point;
        }
        if (!polygon.isEmpty())
            polygon << polygon.first();
        path.addPolygon(polygon);
    }
    return path;
}

// A zone's extent on the screen: its corners' box projected (Web Mercator keeps the box a box).
QRectF ZoneLayer::screenBox(const Outline &outline, const MapViewport &view)
{
    if (outline.box.isNull())
        return {};
    const QPointF northWest = view.geoToScreen(QGeoCoordinate(outline.box.bottom(), outline.box.left()));
    const QPointF southEast = view.geoToScreen(QGeoCoordinate(outline.box.top(), outline.box.right()));
    return QRectF(northWest, southEast).normalized();
}

int ZoneLayer::zoneAt(QPointF position) const
{
    const MapViewport view = viewport();
    for (int row = int(m_outlines.size()) - 1; row >= 0; --row) {
        const Outline &outline = m_outlines[size_t(row)];
        if (screenBox(outline, view).adjusted(-1, -1, 1, 1).contains(position) && pathOf(outline, view).contains(position))
            return row;
    }
    return -1;
}

QString ZoneLayer::describe(int row) const
{
    if (!m_airspace || row < 0 || row >= m_airspace->count())
        return {};
    const Zone &z = m_airspace->zoneAt(row);
    const Airspace::Group group = m_airspace->groupOf(row);
    const QString source = group == Airspace::Group::Server ? airspace::sourceName(z.source)
                         : group == Airspace::Group::Custom ? tr("drawn on the map") : Airspace::groupName(group);
    const bool sayOrigin = !z.origin.isEmpty() && group != Airspace::Group::Custom;
    QString text = tr("%1 (%2 zone)\nSource: %3%4\nFloor %5, ceiling %6")
                       .arg(z.name, airspace::kindName(z.kind), source, sayOrigin ? QStringLiteral(" — ") + z.origin : QString(),
                            airspace::limitText(z.floor, false), airspace::limitText(z.ceiling, true));
    if (const airspace::ed::GeoZone *g = z.geoZone.get()) {
        text += tr("\n%1 (%2 %3)").arg(airspace::ed::restrictionWords(g->restriction), g->identifier, airspace::ed::restrictionName(g->restriction));
        if (!g->message.isEmpty())
            text += QLatin1Char('\n') + g->message;
        if (!g->reasons.isEmpty() || !g->otherReasonInfo.isEmpty())
            text += tr("\nReason: %1").arg((g->reasons + QStringList{g->otherReasonInfo}).filter(QRegularExpression(QStringLiteral("\\S"))).join(QStringLiteral(", ")));
        text += tr("\nWhen: %1").arg(airspace::ed::applicabilityText(g->applicability, QTimeZone::systemTimeZone()));
        if (!m_airspace->appliesToFlight(row))
            text += tr("\nNot in force during the planned flight");
        for (const airspace::ed::Authority &a : g->authorities)
            text += tr("\nAuthority: %1").arg(airspace::ed::contactText(a));
    }
    if (const QString problem = m_airspace->problemOf(row); !problem.isEmpty())
        text += tr("\nNot checked: %1").arg(problem);
    else if (!z.active)
        text += tr("\nSwitched off: not checked");
    return text;
}

QPointF ZoneLayer::zoneCentre(int row) const
{
    if (row < 0 || row >= int(m_outlines.size()) || !m_outlines[size_t(row)].centre.isValid())
        return {qQNaN(), qQNaN()};
    return viewport().geoToScreen(m_outlines[size_t(row)].centre);
}

std::vector<QRectF> ZoneLayer::placedLabels() const
{
    std::vector<QRectF> out;
    for (int i = 0; i < labelCount(); ++i)
        out.push_back(labelRect(i));
    return out;
}

QRectF ZoneLayer::labelRect(int index) const
{
    return index >= 0 && index < labelCount() ? m_labels[size_t(index)].rect.translated(paintOrigin()) : QRectF();
}

int ZoneLayer::labelZone(int index) const
{
    return index >= 0 && index < labelCount() ? m_labels[size_t(index)].row : -1;
}

void ZoneLayer::hoverAt(QPointF position)
{
    const int row = zoneAt(position);
    const QString text = describe(row);
    if (text == m_hoverText && (text.isEmpty() || position == m_hoverPosition))
        return;
    m_hoverText = text;
    m_hoverPosition = position;
    emit hoverChanged();
}

void ZoneLayer::paint(QPainter *painter)
{
    QPainter &p = *painter;
    p.setRenderHint(QPainter::Antialiasing);
    const std::vector<Label> before = std::move(m_labels);
    m_labels.clear();
    const auto done = [&] {
        const bool moved = before.size() != m_labels.size()
            || !std::equal(before.begin(), before.end(), m_labels.begin(), [](const Label &a, const Label &b) { return a.rect == b.rect; });
        emit drawn();
        if (moved)
            emit labelsPlaced();  // the layers above keep their labels clear of these
    };
    if (!m_airspace) {
        done();
        return;
    }
    const MapViewport &view = paintViewport();
    const int selected = m_airspace->selectedZone();
    std::vector<QPainterPath> paths(m_outlines.size());
    // Drawn: what reaches into the painted area (halos and pens included).
    const QRectF painted = QRectF(QPointF(0, 0), view.size()).adjusted(-8, -8, 8, 8);
    for (size_t row = 0; row < m_outlines.size(); ++row) {
        const Zone &z = m_airspace->zoneAt(int(row));
        if (!painted.intersects(screenBox(m_outlines[row], view)))
            continue;
        paths[row] = pathOf(m_outlines[row], view);
        const QPainterPath &path = paths[row];
        if (int(row) == selected) {
            p.setPen(QPen(colours().selection, 8, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            p.setBrush(Qt::NoBrush);
            p.drawPath(path);
        }
        const QColor colour = zoneColour(colours(), z);
        const bool keepOut = keepsOut(z.kind, z.geoZone ? std::optional(z.geoZone->restriction) : std::nullopt);
        if (!z.active) {
            p.setPen(QPen(colours().inactiveEdge, 1.5, Qt::DashLine));
            p.setBrush(Qt::NoBrush);
        } else if (!m_airspace->appliesToFlight(int(row))) {
            // In force, but not while the route flies: its colour, dashed, no wash.
            p.setPen(QPen(colour, 2, Qt::DashLine));
            p.setBrush(Qt::NoBrush);
        } else if (z.kind == airspace::ZoneKind::Exclusion) {
            QColor wash = colour;
            wash.setAlpha(28);
            // A hatch needs room to show: a zone a few pixels wide is its wash and outline, drawn at
            // once. Only a zone that keeps the flight out is hatched; one with conditions is washed.
            const QRectF box = path.boundingRect();
            if (keepOut && std::max(box.width(), box.height()) >= kHatchedSize) {
                p.setPen(Qt::NoPen);
                p.setBrush(wash);
                p.drawPath(path);
                p.setBrush(QBrush(colour, Qt::BDiagPattern));
            } else {
                p.setBrush(wash);
            }
            p.setPen(QPen(colour, 2));
        } else {
            p.setPen(QPen(colour, 3));
            p.setBrush(Qt::NoBrush);
        }
        p.drawPath(path);
    }

    // Labels: the chosen zone's first, then active exclusion zones, the rest after; each just above
    // its zone's outline (a route through the zone does not cover it), stacked down where another
    // label is (a leader line back to the zone), left out where it would still overlap one.
    const QFont nameFont = labelFont(p.font(), true), limitFont = labelFont(p.font(), false);
    const QFontMetricsF nameMetrics(nameFont), limitMetrics(limitFont);
    const double labelHeight = nameMetrics.height() + limitMetrics.height() + 2 * kLabelPadding;
    std::vector<int> order;
    std::vector<QPointF> anchors(m_outlines.size(), QPointF(-1e9, -1e9));
    const QRectF visible(QPointF(0, 0), view.size());
    for (size_t row = 0; row < m_outlines.size(); ++row) {
        const QRectF box = paths[row].boundingRect();
        if (box.isEmpty() || !visible.intersects(box) || (std::max(box.width(), box.height()) < kLabelledSize && int(row) != selected))
            continue;
        // LabelPlacer puts a label at its mark + kOffset, centred on the mark's height.
        anchors[row] = QPointF(box.left(), box.top() - 2 - labelHeight / 2) - LabelPlacer::kOffset;
        order.push_back(int(row));
    }
    const auto rank = [&](int row) {
        const Zone &z = m_airspace->zoneAt(row);
        return row == selected ? 0 : z.active && z.kind == airspace::ZoneKind::Exclusion ? 1 : 2;
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return rank(a) < rank(b); });
    LabelPlacer placer(anchors, 0); // the anchors are only where labels go: the zones themselves may be covered
    for (const int row : order) {
        const QStringList lines = labelText(m_airspace->zoneAt(row)).split(QLatin1Char('\n'));
        const QSizeF size(std::max(nameMetrics.horizontalAdvance(lines[0]), limitMetrics.horizontalAdvance(lines[1])) + 2 * kLabelPadding,
                          labelHeight);
        const LabelPlacer::Placement placement = placer.place(size_t(row), size);
        const QRectF rect = placement.rect;
        const bool overlaps = std::any_of(m_labels.begin(), m_labels.end(), [&](const Label &l) { return l.rect.intersects(rect); });
        if (overlaps)
            continue;
        m_labels.push_back({row, rect});
        const Zone &z = m_airspace->zoneAt(row);
        const QColor ink = !z.active ? colours().inactive : zoneColour(colours(), z).darker(z.kind == airspace::ZoneKind::Exclusion ? 130 : 120);
        if (placement.moved) {
            const QRectF box = paths[size_t(row)].boundingRect();
            p.setPen(QPen(ink, 1, Qt::DotLine));
            p.drawLine(QPointF(rect.left(), rect.center().y()), QPointF(box.left(), box.top()));
        }
        p.setPen(QPen(ink, 1));
        p.setBrush(colours().labelBox);
        p.drawRoundedRect(rect, 3, 3);
        p.setFont(nameFont);
        p.drawText(QPointF(rect.left() + kLabelPadding, rect.top() + kLabelPadding + nameMetrics.ascent()), lines[0]);
        p.setFont(limitFont);
        p.drawText(QPointF(rect.left() + kLabelPadding, rect.top() + kLabelPadding + nameMetrics.height() + limitMetrics.ascent()), lines[1]);
    }
    done();
}

} // namespace sortie::ui
