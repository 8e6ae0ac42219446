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

    bool hasPosition() const { return !std::isnan(position.x()); }
    bool hasHome() const { return !std::isnan(home.x()); }
    // What it is drawn in: grey while its data is stale.
    QColor shownColor() const { return stale ? QColor(0x90, 0x90, 0x90) : color; }
};

} // namespace sortie::ui
