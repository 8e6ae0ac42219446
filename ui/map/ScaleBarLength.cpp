#include "ScaleBarLength.h"

#include <cmath>
#include <QCoreApplication>

namespace sortie::ui {

namespace {

constexpr double kFoot = 0.3048;
constexpr double kMile = 1609.344;

// Largest 1/2/5 x 10^n not above `limit`.
double roundDown(double limit)
{
    const double power = std::pow(10.0, std::floor(std::log10(limit)));
    for (double factor : {5.0, 2.0, 1.0}) {
        if (factor * power <= limit)
            return factor * power;
    }
    return power;
}

} // namespace

ScaleBarLength ScaleBarLength::choose(double metersPerPixel, double maxPixels, bool imperial)
{
    if (!(metersPerPixel > 0) || !(maxPixels > 0))
        return {};
    const double maxMeters = metersPerPixel * maxPixels;
    if (!imperial) {
        const double meters = roundDown(maxMeters);
        const QString label = meters >= 1000 ? QCoreApplication::translate("ScaleBarLength", "%1 km").arg(meters / 1000.0)
                                             : QStringLiteral("%1 m").arg(meters);
        return {meters / metersPerPixel, label};
    }
    if (maxMeters >= kMile) {
        const double miles = roundDown(maxMeters / kMile);
        return {miles * kMile / metersPerPixel, QCoreApplication::translate("ScaleBarLength", "%1 mi").arg(miles)};
    }
    const double feet = roundDown(maxMeters / kFoot);
    return {feet * kFoot / metersPerPixel, QCoreApplication::translate("ScaleBarLength", "%1 ft").arg(feet)};
}

} // namespace sortie::ui
