#include "WebMercator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::ui::WebMercator {

double clampLatitude(double latitude)
{
    return std::clamp(latitude, -kMaxLatitude, kMaxLatitude);
}

QPointF project(double latitude, double longitude)
{
    const double lat = clampLatitude(latitude) * std::numbers::pi / 180.0;
    const double x = (longitude + 180.0) / 360.0;
    const double y = (1.0 - std::asinh(std::tan(lat)) / std::numbers::pi) / 2.0;
    return {x, y};
}

QPointF project(const QGeoCoordinate &coordinate)
{
    return project(coordinate.latitude(), coordinate.longitude());
}

QGeoCoordinate unproject(QPointF normalised)
{
    double x = normalised.x() - std::floor(normalised.x());
    const double y = std::clamp(normalised.y(), 0.0, 1.0);
    double longitude = x * 360.0 - 180.0;
    if (longitude >= 180.0)
        longitude -= 360.0;
    const double latitude = std::atan(std::sinh(std::numbers::pi * (1.0 - 2.0 * y))) * 180.0 / std::numbers::pi;
    return QGeoCoordinate(latitude, longitude);
}

double worldSize(double zoom)
{
    return kTileSize * std::exp2(zoom);
}

double metersPerPixel(double latitude, double zoom)
{
    const double circumference = 2.0 * std::numbers::pi * kEarthRadius;
    return circumference * std::cos(clampLatitude(latitude) * std::numbers::pi / 180.0) / worldSize(zoom);
}

} // namespace sortie::ui::WebMercator
