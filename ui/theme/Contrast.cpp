#include "Contrast.h"

#include <algorithm>
#include <cmath>

namespace sortie::ui::contrast {

namespace {
double linear(double channel)
{
    return channel <= 0.04045 ? channel / 12.92 : std::pow((channel + 0.055) / 1.055, 2.4);
}
} // namespace

double relativeLuminance(const QColor &colour)
{
    const QColor rgb = colour.toRgb();
    return 0.2126 * linear(rgb.redF()) + 0.7152 * linear(rgb.greenF()) + 0.0722 * linear(rgb.blueF());
}

double ratio(const QColor &a, const QColor &b)
{
    const double la = relativeLuminance(a);
    const double lb = relativeLuminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

QColor over(const QColor &top, const QColor &bottom)
{
    const QColor t = top.toRgb();
    const QColor b = bottom.toRgb();
    const double alpha = t.alphaF();
    auto mix = [alpha](double upper, double lower) { return upper * alpha + lower * (1.0 - alpha); };
    return QColor::fromRgbF(float(mix(t.redF(), b.redF())), float(mix(t.greenF(), b.greenF())),
                            float(mix(t.blueF(), b.blueF())));
}

} // namespace sortie::ui::contrast
