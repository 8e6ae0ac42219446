#pragma once

#include "MapPalette.h"
#include "VehicleMark.h"

#include <QFont>
#include <QRectF>

class QPainter;

namespace sortie::ui {

// How one vehicle looks on the map: an arrow turned to its heading (the current one ringed and
// larger), its home as an "H" square, its label on a tag (the current one's filled) with a leader
// line when the label was stacked away from it. Positions are in the painter's pixels.
class VehiclePainter
{
public:
    // The labels' font: what label sizes are measured with.
    static QFont labelFont();
    // A label's tag around its text.
    static QSizeF labelSize(const QString &label);

    VehiclePainter(QPainter &painter, const MapPalette &colours);

    void paintHome(const VehicleMark &vehicle, QPointF home);
    void paintArrow(const VehicleMark &vehicle, QPointF at, bool current);
    void paintLabel(const VehicleMark &vehicle, QPointF at, const QRectF &label, bool moved, bool current);

private:
    QPainter &m_painter;
    const MapPalette &m_colours;
};

} // namespace sortie::ui
