#include "EnduranceLayer.h"

#include "FollowOwner.h"
#include "RouteEndurance.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace sortie::ui {

namespace {
QGeoCoordinate positionOf(const endurance::RoutePlace &place)
{
    return QGeoCoordinate(place.position.latitude, place.position.longitude);
}

// The label right of `at`, or left of `leftEnd` where it would run under the map's zoom buttons or
// past its edge (`right`).
void drawLabel(QPainter &p, QPointF at, double leftEnd, double right, const QString &text, const QColor &colour, const QColor &halo)
{
    QPainterPath path;
    QFont font = p.font();
    font.setBold(true);
    const double width = QFontMetricsF(font).horizontalAdvance(text);
    if (at.x() + width > right - 56)
        at.setX(leftEnd - width);
    path.addText(at, font, text);
    p.setPen(QPen(halo, 3.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    p.setBrush(Qt::NoBrush);
    p.drawPath(path);
    p.setPen(Qt::NoPen);
    p.setBrush(colour.darker(130));
    p.drawPath(path);
}
} // namespace

EnduranceLayer::EnduranceLayer(QQuickItem *parent)
    : MapLayer(parent)
{
}

endurance::RouteEndurance *EnduranceLayer::endurance() const
{
    return m_endurance;
}

void EnduranceLayer::setEndurance(endurance::RouteEndurance *endurance)
{
    if (!followOwner(m_endurance, endurance, this, &endurance::RouteEndurance::estimateChanged, &EnduranceLayer::readMarks))
        return;
    readMarks();
    emit enduranceChanged();
}

void EnduranceLayer::readMarks()
{
    m_marks.clear();
    if (const endurance::EnduranceEstimate *estimate = m_endurance && m_endurance->estimate() ? &*m_endurance->estimate() : nullptr) {
        for (const endurance::BatteryChange &change : estimate->changes) {
            const QGeoCoordinate at = positionOf(change.at);
            if (!at.isValid())
                continue;
            m_marks.push_back({at, change.planned ? Kind::PlannedChange : Kind::UnplannedChange,
                               change.planned ? tr("Battery change") : tr("Battery change needed")});
        }
        if (estimate->pointOfNoReturn)
            if (const QGeoCoordinate at = positionOf(*estimate->pointOfNoReturn); at.isValid())
                m_marks.push_back({at, Kind::NoReturn, tr("No return")});
    }
    repaint();
    emit marksChanged();
}

QPointF EnduranceLayer::markPosition(int index) const
{
    if (index < 0 || index >= markCount())
        return {qQNaN(), qQNaN()};
    return viewport().geoToScreen(m_marks[size_t(index)].position);
}

void EnduranceLayer::paint(QPainter *painter)
{
    QPainter &p = *painter;
    p.setRenderHint(QPainter::Antialiasing);
    const MapViewport &viewport = paintViewport();
    const double right = width() - paintOrigin().x(); // the map's right edge in picture pixels
    const MapPalette &colour = colours();
    for (const Mark &mark : m_marks) {
        const QPointF c = viewport.geoToScreen(mark.position);
        if (mark.kind == Kind::NoReturn) {
            // A diamond, the shape of a warning sign, in red.
            const QPolygonF diamond{c + QPointF(0, -9), c + QPointF(9, 0), c + QPointF(0, 9), c + QPointF(-9, 0)};
            p.setPen(QPen(colour.outline, 2));
            p.setBrush(colour.noReturn);
            p.drawPolygon(diamond);
            drawLabel(p, c + QPointF(13, 5), c.x() - 13, right, mark.label, colour.noReturn, colour.halo);
            continue;
        }
        // A battery: its body and terminal, above the point so the waypoint's number stays visible.
        const QColor fill = mark.kind == Kind::PlannedChange ? colour.planned : colour.unplanned;
        const QRectF body(c.x() - 8, c.y() - 26, 16, 10);
        p.setPen(QPen(colour.outline, 2));
        p.setBrush(fill);
        p.drawRoundedRect(body, 2, 2);
        p.setPen(Qt::NoPen);
        p.drawRect(QRectF(body.right(), body.center().y() - 2.5, 3, 5));
        p.setPen(QPen(fill, 2));
        p.drawLine(c + QPointF(0, -16), c + QPointF(0, -4));
        drawLabel(p, QPointF(body.right() + 7, body.bottom()), body.left() - 5, right, mark.label, fill, colour.halo);
    }
}

} // namespace sortie::ui
