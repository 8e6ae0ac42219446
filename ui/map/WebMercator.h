#pragma once

#include <QGeoCoordinate>
#include <QPointF>

namespace sortie::ui {

// Spherical Web Mercator (EPSG:3857), the projection of XYZ map tiles. Positions are kept
// "normalised": x and y in [0, 1] across the whole world, y growing southwards, so that a
// pixel position at zoom z is the normalised position times worldSize(z).
namespace WebMercator {

inline constexpr double kMaxLatitude = 85.051128779806589;
inline constexpr double kTileSize = 256.0;
inline constexpr double kEarthRadius = 6378137.0;

QPointF project(double latitude, double longitude);
QPointF project(const QGeoCoordinate &coordinate);
// The inverse; x outside [0, 1] wraps around the antimeridian, y is clamped to the map.
QGeoCoordinate unproject(QPointF normalised);
double worldSize(double zoom);
// Ground metres covered by one screen pixel at this latitude and zoom.
double metersPerPixel(double latitude, double zoom);
double clampLatitude(double latitude);

} // namespace WebMercator
} // namespace sortie::ui
