#pragma once

#include "MapLayer.h"

#include <QColor>
#include <QGeoCoordinate>
#include <QPointer>

#include <vector>

namespace sortie::airspace {
class Airspace;
}

namespace sortie::ui {

// Where the open route is inside a zone it must not be in (the store's crossings: each stretch's
// coordinates along the flown path): drawn red over the route, with a white halo, so the operator
// sees which part of which leg the issue list speaks of. Draws what the check found; decides nothing.
class ZoneCrossingLayer : public MapLayer
{
    Q_OBJECT
    Q_MOC_INCLUDE("Airspace.h")
    QML_ELEMENT
    Q_PROPERTY(sortie::airspace::Airspace *airspace READ airspace WRITE setAirspace NOTIFY airspaceChanged)
    Q_PROPERTY(int stretchCount READ stretchCount NOTIFY crossingsChanged)

public:
    explicit ZoneCrossingLayer(QQuickItem *parent = nullptr);

    airspace::Airspace *airspace() const;
    void setAirspace(airspace::Airspace *airspace);
    int stretchCount() const { return int(m_stretches.size()); }
    // The middle of stretch `index` in this item's coordinates (tests); NaN when there is none.
    Q_INVOKABLE QPointF stretchMiddle(int index) const;

    void paint(QPainter *painter) override;


signals:
    void airspaceChanged();
    void crossingsChanged();

private:
    void readCrossings();

    QPointer<airspace::Airspace> m_airspace;
    std::vector<std::vector<QGeoCoordinate>> m_stretches;
};

} // namespace sortie::ui
