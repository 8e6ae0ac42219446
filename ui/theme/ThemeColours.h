#pragma once

#include "MapPalette.h"

#include <QColor>
#include <QPalette>

namespace sortie::ui {

// One scheme's colours: the controls' palette roles, the states (problem, warning, ok, info,
// missing) as a fill and as words readable on the window and on a field, and what is painted in
// C++ (MapPalette). A value: Theme holds the one in use and tst_theme judges every scheme's pairs.
struct ThemeColours
{
    // The controls' roles (QPalette's names).
    QColor window, windowText, base, alternateBase, text, button, buttonText, highlight, highlightedText,
        placeholderText, toolTipBase, toolTipText, link, light, midlight, mid, dark, shadow;

    // States. The fill (a dot, a bar, a banner) and the words in that state's colour, readable on
    // `window` and `base`; `onProblem` / `onWarning` are the words on a problem or warning fill.
    QColor problem, warning, ok, info, missing;
    QColor problemText, warningText, okText, infoText, missingText;
    QColor onProblem, onWarning, onReplay;

    // A notice box (a route's version conflict): its background, words and border.
    QColor noticeBackground, noticeText, noticeBorder;
    // Boxes over the map (the scale, the map's controls) and their words.
    QColor overlay, overlayText;
    // The map pane's edge while a tool is on, and the replay's marks (onReplay: words on them).
    QColor accent, replay;
    // A table's chosen row and every other row (translucent, over `base`).
    QColor rowSelected, rowStripe;

    MapPalette map;

    static ThemeColours lightScheme();
    static ThemeColours darkScheme();
    // High-contrast dark for sunlight: every pair of words and ground reaches 7:1.
    static ThemeColours sunlightScheme();
    // The platform's palette for the controls, with the light or dark states to suit it.
    static ThemeColours fromPlatform(const QPalette &platform);

    bool isDark() const;
    bool operator==(const ThemeColours &) const = default;
};

} // namespace sortie::ui
