#include "ZoneCrossingLayer.h"

#include "Airspace.h"
#include "FollowOwner.h"

#include <QPainter>

namespace sortie::ui {

ZoneCrossingLayer::ZoneCrossingLayer(QQuickItem *parent)
    : MapLayer(parent)
{
    setAcceptedMouseButtons(Qt::NoButton); // only drawn: clicks go on to the route under it
}

airspace::Airspace *ZoneCrossingLayer::airspace() const
{
    return m_airspace;
}

void ZoneCrossingLayer::setAirspace(airspace::Airspace *airspace)
{
    if (!followOwner(m_airspace, airspace, this, &airspace::Airspace::crossingsChanged, &ZoneCrossingLayer::readCrossings))
        return;
    readCrossings();
    emit airspaceChanged();
}

void ZoneCrossingLayer::readCrossings()
{
    m_stretches.clear();
    if (m_airspace) {
        for (const airspace::ZoneCrossing &c : m_airspace->crossings()) {
            std::vector<QGeoCoordinate> stretch;
            for (const mission::GeoPoint &p : c.path)
                if (const QGeoCoordinate coordinate(p.latitude, p.longitude); coordinate.isValid())
                    stretch.push_back(coordinate);
            if (stretch.size() >= 2)
                m_stretches.push_back(std::move(stretch));
        }
    }
    repaint();
    emit crossingsChanged();
}

QPointF ZoneCrossingLayer::stretchMiddle(int index) const
{
    if (index < 0 || index >= stretchCount())
        return {qQNaN(), qQNaN()};
    const auto &s = m_stretches[size_t(index)];
    const QPointF a = viewport().geoToScreen(s.front()), b = viewport().geoToScreen(s.back());
    return (a + b) / 2;
}

void ZoneCrossingLayer::paint(QPainter *painter)
{
    QPainter &p = *painter;
    p.setRenderHint(QPainter::Antialiasing);
    const MapViewport &view = paintViewport();
    for (const auto &stretch : m_stretches) {
        QPolygonF line;
        for (const QGeoCoordinate &c : stretch)
            line << view.geoToScreen(c);
        p.setPen(QPen(colours().halo, 9, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolyline(line);
        p.setPen(QPen(colours().crossing, 5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolyline(line);
    }
}

} // namespace sortie::ui
