#pragma once

#include <QString>

namespace sortie::ui {

// The longest round distance (1, 2 or 5 times a power of ten, in metres and kilometres or in
// feet and miles) that fits in a bar of at most `maxPixels`.
struct ScaleBarLength
{
    double pixels = 0;
    QString label;

    static ScaleBarLength choose(double metersPerPixel, double maxPixels, bool imperial);
};

} // namespace sortie::ui
