#include "PhotoLayer.h"

#include "FollowOwner.h"
#include "PhotoSurvey.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace sortie::ui {

PhotoLayer::PhotoLayer(QQuickItem *parent)
    : MapLayer(parent)
{
}

void PhotoLayer::setSurvey(coverage::PhotoSurvey *survey)
{
    if (!followOwner(m_survey, survey, this, &coverage::PhotoSurvey::resultChanged, &PhotoLayer::readMarks))
        return;
    readMarks();
    emit surveyChanged();
}

void PhotoLayer::readMarks()
{
    m_photos.clear();
    m_holes.clear();
    if (m_survey) {
        for (const geotag::TaggedPhoto &p : m_survey->placedPhotos())
            m_photos.emplace_back(p.position.latitude, p.position.longitude);
        for (const coverage::Hole &h : m_survey->holes()) {
            HoleMark mark;
            for (const auto &[lon, lat] : h.ring)
                mark.ring.emplace_back(lat, lon);
            mark.centre = QGeoCoordinate(h.centreLatitude, h.centreLongitude);
            mark.label = tr("Hole %1 m²").arg(std::lround(h.areaSquareMeters));
            m_holes.push_back(std::move(mark));
        }
    }
    repaint();
    emit marksChanged();
}

QPointF PhotoLayer::photoPosition(int index) const
{
    if (index < 0 || index >= photoCount())
        return {qQNaN(), qQNaN()};
    return viewport().geoToScreen(m_photos[size_t(index)]);
}

QPointF PhotoLayer::holePosition(int index) const
{
    if (index < 0 || index >= holeCount())
        return {qQNaN(), qQNaN()};
    return viewport().geoToScreen(m_holes[size_t(index)].centre);
}

void PhotoLayer::paint(QPainter *painter)
{
    QPainter &p = *painter;
    p.setRenderHint(QPainter::Antialiasing);
    const MapViewport &viewport = paintViewport();
    const MapPalette &colour = colours();
    // The holes under the dots: shaded, outlined, named with their area.
    for (const HoleMark &hole : m_holes) {
        QPolygonF ring;
        for (const QGeoCoordinate &c : hole.ring)
            ring << viewport.geoToScreen(c);
        QColor shade = colour.noReturn;
        shade.setAlphaF(0.30);
        p.setPen(QPen(colour.noReturn, 2));
        p.setBrush(shade);
        p.drawPolygon(ring);
        QFont font = p.font();
        font.setBold(true);
        QPainterPath text;
        text.addText(viewport.geoToScreen(hole.centre) + QPointF(-QFontMetricsF(font).horizontalAdvance(hole.label) / 2, 4), font, hole.label);
        p.setPen(QPen(colour.halo, 3.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.setBrush(Qt::NoBrush);
        p.drawPath(text);
        p.setPen(Qt::NoPen);
        p.setBrush(colour.noReturn.darker(130));
        p.drawPath(text);
    }
    // Each photo where it was taken: a small dot with an outline, so hundreds stay readable.
    p.setPen(QPen(colour.outline, 1));
    p.setBrush(colour.planned);
    for (const QGeoCoordinate &c : m_photos)
        p.drawEllipse(viewport.geoToScreen(c), 3.5, 3.5);
}

} // namespace sortie::ui
