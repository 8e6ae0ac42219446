#pragma once

#include "RouteFrame.h"

#include <QColor>
#include <QFont>
#include <QHash>
#include <QImage>
#include <QStaticText>

class QPainter;

namespace sortie::ui {

// Draws a RouteFrame: legs with a halo so they read on any map, numbered markers for labelled
// waypoints, dots for the rest, selection and the current waypoint highlighted, a badge on a
// labelled waypoint with actions (green: camera, purple: other actions, both: split). Markers are
// blitted from sprites drawn once (an antialiased circle per waypoint would cost a path fill
// each), and number texts are laid out once; both are kept between frames. The still part and
// the moving part (a drag) are drawn separately, into different pictures.
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
        QColor cameraMark{0x2e, 0x7d, 0x32};  // a waypoint that takes photos or video
        QColor actionMark{0x6a, 0x1b, 0x9a};  // a waypoint with other actions (wait, heading, ...)
        double legWidth = 3.0;
        double markerRadius = 9.0;
        bool operator==(const Style &) const = default;
    };

    // Everything but the moving part.
    void paintStill(QPainter &painter, const RouteFrame &frame, const Style &style);
    // The moving part, drawn into a picture whose top-left corner is `origin` in frame pixels.
    void paintMoving(QPainter &painter, const RouteFrame &frame, const Style &style, QPointF origin);
    // What the moving part covers, in frame pixels (empty when nothing moves).
    static QRectF movingBounds(const RouteFrame &frame, const Style &style);

private:
    void setUp(QPainter &painter, const Style &style);
    void paintLegs(QPainter &painter, const std::vector<QPolygonF> &legs);
    void paintMarkers(QPainter &painter, const std::vector<RouteFrame::Marker> &markers);
    const QStaticText &number(int value);
    // The marker without its number: flags (labelled, selected, current) and digit count pick it.
    const QImage &sprite(quint8 flags, int digits);
    QImage drawSprite(quint8 flags, int digits) const;
    // The small badge at a labelled marker's upper right that says it has actions.
    const QImage &markSprite(quint8 marks);

    Style m_style;
    qreal m_dpr = 0;
    QFont m_font;
    QHash<int, QStaticText> m_numbers;
    QHash<int, QImage> m_sprites;
    QHash<int, QImage> m_markSprites;
};

} // namespace sortie::ui
