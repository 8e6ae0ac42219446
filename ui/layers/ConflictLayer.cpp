#include "ConflictLayer.h"

#include "FollowOwner.h"
#include "RouteDeconfliction.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace sortie::ui {

ConflictLayer::ConflictLayer(QQuickItem *parent)
    : MapLayer(parent)
{
}

deconfliction::RouteDeconfliction *ConflictLayer::deconfliction() const
{
    return m_deconfliction;
}

void ConflictLayer::setDeconfliction(deconfliction::RouteDeconfliction *deconfliction)
{
    if (!followOwner(m_deconfliction, deconfliction, this, &deconfliction::RouteDeconfliction::conflictsChanged, &ConflictLayer::readMarks))
        return;
    readMarks();
    emit deconflictionChanged();
}

void ConflictLayer::readMarks()
{
    m_marks.clear();
    if (m_deconfliction) {
        for (const deconfliction::FleetConflict &c : m_deconfliction->conflicts()) {
            const deconfliction::Conflict &k = c.conflict;
            const QGeoCoordinate own(k.firstAt.position.latitude, k.firstAt.position.longitude);
            const QGeoCoordinate other(k.secondAt.position.latitude, k.secondAt.position.longitude);
            if (!own.isValid() || !other.isValid())
                continue;
            const long s = std::lround(k.time);
            m_marks.push_back({own, other,
                               tr("%1 at %2:%3, %4 m / %5 m")
                                   .arg(c.otherName)
                                   .arg(s / 60)
                                   .arg(s % 60, 2, 10, QLatin1Char('0'))
                                   .arg(k.horizontal, 0, 'f', 0)
                                   .arg(k.vertical, 0, 'f', 0)});
        }
    }
    repaint();
    emit conflictsChanged();
}

QPointF ConflictLayer::markPosition(int index) const
{
    if (index < 0 || index >= markCount())
        return {qQNaN(), qQNaN()};
    return viewport().geoToScreen(m_marks[size_t(index)].own);
}

void ConflictLayer::paint(QPainter *painter)
{
    QPainter &p = *painter;
    p.setRenderHint(QPainter::Antialiasing);
    const MapViewport &viewport = paintViewport();
    const double right = width() - paintOrigin().x();
    QFont font = p.font();
    font.setBold(true);
    const QFontMetricsF metrics(font);
    for (const Mark &mark : m_marks) {
        const QPointF a = viewport.geoToScreen(mark.own), b = viewport.geoToScreen(mark.other);
        p.setPen(QPen(colours().conflict, 2, Qt::DashLine));
        p.drawLine(a, b);
        p.setPen(QPen(colours().conflict, 3));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(a, 10, 10);
        p.setPen(QPen(colours().outline, 1.5));
        p.setBrush(colours().conflict);
        p.drawEllipse(b, 6, 6);
        // The label below the ring, moved left where it would run past the map's right edge.
        QPointF at = a + QPointF(14, 18);
        const double w = metrics.horizontalAdvance(mark.label);
        if (at.x() + w > right - 56)
            at.setX(a.x() - 14 - w);
        QPainterPath path;
        path.addText(at, font, mark.label);
        p.setPen(QPen(colours().halo, 3.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
        p.setPen(Qt::NoPen);
        p.setBrush(colours().conflict.darker(120));
        p.drawPath(path);
    }
}

} // namespace sortie::ui
