#pragma once

#include "MapPalette.h"
#include "MapViewport.h"

#include <QFont>
#include <QMarginsF>
#include <QRectF>
#include <QString>

#include <vector>

class QFontMetrics;
class QPainter;

namespace sortie::ui {

// Lines of latitude and longitude at a round interval that suits the zoom, labelled at the
// top and left edges of the view. The labels stay inside two bands along those edges
// (labelBands): map controls placed clear of the bands never cover a label.
class Graticule
{
public:
    struct Label
    {
        QPointF baseline; // where the text is drawn
        QRectF rect;      // what it covers, in view pixels
        QString text;
    };
    static QFont labelFont(const QFont &base);
    static std::vector<Label> labels(const MapViewport &viewport, const QFontMetrics &metrics);
    // The top band (longitude labels) and left band (latitude labels, as wide as the widest one
    // can be at any zoom), in pixels.
    static QMarginsF labelBands(const QFontMetrics &metrics);
    // The interval in degrees for lines about `minimumPixels` apart or more.
    static double interval(const MapViewport &viewport, double minimumPixels = 110.0);
    static void paint(QPainter &painter, const MapViewport &viewport, const MapPalette &palette);
    static QString label(double degrees, double interval, bool latitude);
};

} // namespace sortie::ui
