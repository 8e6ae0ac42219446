#include "TrafficLayer.h"

#include "LabelPlacer.h"
#include "Traffic.h"
#include "TrafficPicture.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::ui {
namespace {

constexpr double kFoot = 0.3048;

QFont labelFont()
{
    QFont font;
    font.setPixelSize(11);
    font.setBold(true);
    return font;
}

constexpr double kArrowRoom = 10; // the vertical-trend arrow after the altitude

QSizeF labelSize(const QString &callsign, const QString &altitude)
{
    const QFontMetricsF metrics(labelFont());
    const double width = std::max(metrics.horizontalAdvance(callsign), metrics.horizontalAdvance(altitude) + kArrowRoom);
    return QSizeF(width + 8, 2 * metrics.height() + 4);
}

// A chevron pointing up (north), 18 px long: rotated to the track.
QPainterPath chevron()
{
    QPainterPath path;
    path.moveTo(0, -9);
    path.lineTo(7, 8);
    path.lineTo(0, 4);
    path.lineTo(-7, 8);
    path.closeSubpath();
    return path;
}

} // namespace

TrafficLayer::TrafficLayer(QQuickItem *parent)
    : MapLayer(parent)
{
}

void TrafficLayer::setTraffic(traffic::Traffic *traffic)
{
    if (traffic == m_traffic)
        return;
    if (m_traffic)
        disconnect(m_traffic->picture(), nullptr, this, nullptr);
    m_traffic = traffic;
    if (m_traffic) {
        connect(m_traffic->picture(), &traffic::TrafficPicture::changed, this, [this] {
            layOut();
            repaint();
        });
    }
    layOut();
    tellView();
    repaint();
    emit trafficChanged();
}

void TrafficLayer::setImperial(bool imperial)
{
    if (imperial == m_imperial)
        return;
    m_imperial = imperial;
    layOut();
    repaint();
    emit trafficChanged();
}

void TrafficLayer::onViewportChanged()
{
    layOut();
    tellView();
    MapLayer::onViewportChanged();
}

// The server is asked about the circle around the map's centre that reaches its corners.
void TrafficLayer::tellView()
{
    if (!m_traffic || !isVisible() || !map())
        return;
    const MapViewport view = viewport();
    if (view.size().isEmpty())
        return;
    const QGeoCoordinate centre = view.screenToGeo(QPointF(view.size().width() / 2, view.size().height() / 2));
    const double radius = std::hypot(view.size().width(), view.size().height()) / 2 * view.metersPerPixel();
    m_traffic->lookAt(centre.latitude(), centre.longitude(), radius);
}

void TrafficLayer::layOut()
{
    m_marks.clear();
    if (!m_traffic) {
        emit drawn();
        return;
    }
    const MapViewport &viewport = paintViewport();
    const double metresPerPixel = viewport.metersPerPixel();
    for (const traffic::TrafficAircraft &aircraft : m_traffic->picture()->aircraft()) {
        const traffic::TrafficReport &s = aircraft.state;
        if (!s.latitude || !s.longitude)
            continue;
        Mark m;
        m.at = viewport.geoToScreen(QGeoCoordinate(*s.latitude, *s.longitude));
        m.vectorEnd = m.at;
        m.trackDeg = s.trackDeg;
        if (s.trackDeg && s.groundSpeedMps && metresPerPixel > 0) {
            const double pixels = *s.groundSpeedMps * kVectorSeconds / metresPerPixel;
            const double track = *s.trackDeg * std::numbers::pi / 180.0;
            m.vectorEnd = m.at + QPointF(std::sin(track), -std::cos(track)) * pixels;
        }
        m.callsign = s.callsign.value_or(traffic::TrafficPicture::addressText(s));
        if (s.altitudeM) {
            m.altitude = m_imperial ? tr("%1 ft").arg(std::lround(*s.altitudeM / kFoot / 10) * 10)
                                    : tr("%1 m").arg(std::lround(*s.altitudeM));
            if (s.altitudeReference == traffic::AltitudeReference::Barometric)
                m.altitude += tr(" std");
        }
        if (s.verticalRateMps && std::abs(*s.verticalRateMps) > kClimbThresholdMps)
            m.trend = *s.verticalRateMps > 0 ? 1 : -1;
        m.stale = aircraft.stale;
        m_marks.push_back(m);
    }
    std::vector<QPointF> points;
    for (const Mark &m : m_marks)
        points.push_back(m.at);
    std::vector<size_t> order(m_marks.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::stable_partition(order.begin(), order.end(), [this](size_t i) { return !m_marks[i].stale; });
    LabelPlacer placer(std::move(points));
    for (const QRectF &label : labelsToKeepClearOf())
        placer.keepClear(label);
    for (size_t i : order) {
        const auto placement = placer.place(i, labelSize(m_marks[i].callsign, m_marks[i].altitude));
        m_marks[i].label = placement.rect;
        m_marks[i].labelMoved = placement.moved;
    }
    emit drawn();
}

QPointF TrafficLayer::aircraftPosition(int index) const
{
    if (index < 0 || index >= drawnCount())
        return {qQNaN(), qQNaN()};
    return m_marks[size_t(index)].at + paintOrigin();
}

QRectF TrafficLayer::labelRect(int index) const
{
    if (index < 0 || index >= drawnCount())
        return {};
    return m_marks[size_t(index)].label.translated(paintOrigin());
}

QString TrafficLayer::labelText(int index) const
{
    if (index < 0 || index >= drawnCount())
        return {};
    const Mark &m = m_marks[size_t(index)];
    const QString trend = m.trend > 0 ? tr(" climbing") : m.trend < 0 ? tr(" descending") : QString();
    return (m.callsign + QLatin1Char(' ') + m.altitude + trend).trimmed();
}

bool TrafficLayer::isStale(int index) const
{
    return index >= 0 && index < drawnCount() && m_marks[size_t(index)].stale;
}

void TrafficLayer::paint(QPainter *painter)
{
    QPainter &p = *painter;
    p.setRenderHint(QPainter::Antialiasing);
    static const QPainterPath shape = chevron();
    const QColor colour = colours().traffic;
    const QFont font = labelFont();
    const QFontMetricsF metrics(font);
    p.setFont(font);
    for (const Mark &m : m_marks) {
        p.setOpacity(m.stale ? 0.4 : 1.0);
        if (m.vectorEnd != m.at && m.trackDeg) {
            // From the chevron's tip on, so the line does not hide which way the chevron points.
            const double track = *m.trackDeg * std::numbers::pi / 180.0;
            const QPointF tip = m.at + QPointF(std::sin(track), -std::cos(track)) * 9.0;
            p.setPen(QPen(colour, 2, Qt::DashLine, Qt::RoundCap));
            p.drawLine(tip, m.vectorEnd);
        }
        p.save();
        p.translate(m.at);
        p.setPen(QPen(colours().outline, 1.5));
        p.setBrush(colour);
        if (m.trackDeg) {
            p.rotate(*m.trackDeg);
            p.drawPath(shape);
        } else { // no track yet: a diamond, pointing nowhere
            p.drawPolygon(QPolygonF{{0, -7}, {7, 0}, {0, 7}, {-7, 0}});
        }
        p.restore();
        if (m.labelMoved) {
            p.setPen(QPen(colour, 1));
            p.drawLine(m.at, QPointF(m.label.left(), m.label.center().y()));
        }
        p.setPen(QPen(colour, 1));
        p.setBrush(colours().labelBox);
        p.drawRoundedRect(m.label, 3, 3);
        p.setPen(colour.darker(160));
        const QRectF first(m.label.left() + 4, m.label.top() + 2, m.label.width() - 8, metrics.height());
        p.drawText(first, Qt::AlignLeft | Qt::AlignVCenter, m.callsign);
        const QRectF second = first.translated(0, metrics.height());
        p.drawText(second, Qt::AlignLeft | Qt::AlignVCenter, m.altitude);
        if (m.trend != 0) {
            const double x = second.left() + metrics.horizontalAdvance(m.altitude) + kArrowRoom / 2 + 1;
            const double y = second.center().y();
            const double d = m.trend > 0 ? -1 : 1; // up on screen is negative y
            p.setPen(Qt::NoPen);
            p.setBrush(colour.darker(160));
            p.drawPolygon(QPolygonF{{x, y + 5 * d}, {x + 4, y - 3 * d}, {x - 4, y - 3 * d}});
        }
    }
    p.setOpacity(1.0);
}

} // namespace sortie::ui
