#pragma once

#include <QColor>
#include <QPointF>
#include <QString>

#include <cmath>

namespace sortie::ui {

// One vehicle as the vehicle layer shows it: one row of its model, read once per change.
struct VehicleMark
{
    QString id;    // the trail's key: survives the row moving
    QString label;
    QPointF position{qQNaN(), qQNaN()}; // normalised Web Mercator; NaN until reported
    QPointF home{qQNaN(), qQNaN()};
    double heading = 0;
    bool stale = false;
    QColor color; // the row's colour (VehiclePalette)
    QColor staleColor; // the map palette's `stale`, set by the layer that draws it

    bool hasPosition() const { return !std::isnan(position.x()); }
    bool hasHome() const { return !std::isnan(home.x()); }
    // What it is drawn in: grey while its data is stale.
    QColor shownColor() const { return stale ? staleColor : color; }

    // Drawn the same: a row read again with nothing new in it (no position equals no position).
    friend bool operator==(const VehicleMark &a, const VehicleMark &b)
    {
        const auto same = [](QPointF p, QPointF q) {
            return (std::isnan(p.x()) && std::isnan(q.x())) || p == q;
        };
        return a.id == b.id && a.label == b.label && same(a.position, b.position) && same(a.home, b.home)
            && (a.heading == b.heading || (std::isnan(a.heading) && std::isnan(b.heading))) && a.stale == b.stale
            && a.color == b.color;
    }
};

} // namespace sortie::ui
