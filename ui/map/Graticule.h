#pragma once

#include "MapPalette.h"
#include "MapViewport.h"

class QPainter;

namespace sortie::ui {

// Lines of latitude and longitude at a round interval that suits the zoom, labelled at the
// top and left edges of the view.
class Graticule
{
public:
    // The interval in degrees for lines about `minimumPixels` apart or more.
    static double interval(const MapViewport &viewport, double minimumPixels = 110.0);
    static void paint(QPainter &painter, const MapViewport &viewport, const MapPalette &palette);
    static QString label(double degrees, double interval, bool latitude);
};

} // namespace sortie::ui
