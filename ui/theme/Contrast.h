#pragma once

#include <QColor>

namespace sortie::ui::contrast {

// WCAG 2.x relative luminance of an sRGB colour (alpha ignored): 0 for black, 1 for white.
double relativeLuminance(const QColor &colour);
// WCAG contrast ratio of two opaque colours, (L1 + 0.05) / (L2 + 0.05) with L1 the lighter: 1..21.
// Text for reading needs 4.5 (AA), 7 (AAA: the sunlight scheme).
double ratio(const QColor &a, const QColor &b);
// `top` (possibly translucent) laid over the opaque `bottom`: what the eye sees.
QColor over(const QColor &top, const QColor &bottom);

} // namespace sortie::ui::contrast
