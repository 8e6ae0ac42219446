#pragma once

#include <QColor>
#include <QImage>
#include <QPolygonF>

#include <vector>

class QPainter;

namespace sortie::ui {

// Every vehicle trail in one picture that grows as the vehicles move: new pieces are stroked
// onto it, and only a new layout (zoom, long pan, trails cut short, colours changed) draws all
// again. Trails are stroked opaque and the picture is shown translucent, so a trail crossing
// itself or a piece joining the last one looks as one stroke would (no darker overlaps).
class TrailPicture
{
public:
    struct Stroke
    {
        QPolygonF line; // in picture pixels
        QColor color;   // opaque
    };

    // Everything anew on the next paint: these strokes and nothing else.
    void restart(std::vector<Stroke> strokes);
    // Pieces added to the trails since the last paint.
    void add(Stroke stroke);
    // Brings the picture up to date for the painter's device and draws it at `opacity`.
    void paint(QPainter &painter, qreal opacity);

    double width = 2.0;

private:
    void stroke(QPainter &painter, const std::vector<Stroke> &strokes) const;

    QImage m_image;
    std::vector<Stroke> m_pending;
    bool m_restart = true;
};

} // namespace sortie::ui
