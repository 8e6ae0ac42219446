#pragma once

#include "MapLayer.h"

#include <QColor>
#include <QGeoCoordinate>
#include <QVariant>

#include <vector>

namespace sortie::ui {

// Where the open route is inside a zone it must not be in (Airspace.crossings: each stretch's
// coordinates along the flown path): drawn red over the route, with a white halo, so the operator
// sees which part of which leg the issue list speaks of. Draws what it is given; the check decides.
class ZoneCrossingLayer : public MapLayer
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QVariantList crossings READ crossings WRITE setCrossings NOTIFY crossingsChanged)
    Q_PROPERTY(int stretchCount READ stretchCount NOTIFY crossingsChanged)

public:
    explicit ZoneCrossingLayer(QQuickItem *parent = nullptr);

    QVariantList crossings() const { return m_crossings; }
    void setCrossings(const QVariantList &crossings);
    int stretchCount() const { return int(m_stretches.size()); }
    // The middle of stretch `index` in this item's coordinates (tests); NaN when there is none.
    Q_INVOKABLE QPointF stretchMiddle(int index) const;

    void paint(QPainter *painter) override;

    static QColor colour() { return QColor(0xe5, 0x39, 0x35); }

signals:
    void crossingsChanged();

private:
    QVariantList m_crossings;
    std::vector<std::vector<QGeoCoordinate>> m_stretches;
};

} // namespace sortie::ui
