#pragma once

#include "RouteFrame.h"

#include <QColor>
#include <QFont>
#include <QHash>
#include <QStaticText>

class QPainter;

namespace sortie::ui {

// Draws a RouteFrame: legs with a halo so they read on any map, numbered circles for
// labelled waypoints, dots for the rest, selection and the current waypoint highlighted.
// Keeps the number texts laid out between frames.
class RoutePainter
{
public:
    struct Style
    {
        QColor leg{0x1e, 0x88, 0xe5};
        QColor halo{255, 255, 255, 200};
        QColor marker{0x15, 0x65, 0xc0};
        QColor selected{0xff, 0x8f, 0x00};
        QColor current{0xd8, 0x1b, 0x60};
        QColor text{Qt::white};
        double legWidth = 3.0;
        double markerRadius = 9.0;
    };

    void paint(QPainter &painter, const RouteFrame &frame, const Style &style);

private:
    const QStaticText &number(int value);

    QFont m_font;
    QHash<int, QStaticText> m_numbers;
    bool m_fontReady = false;
};

} // namespace sortie::ui
