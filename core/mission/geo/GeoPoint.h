#pragma once

#include <cmath>

namespace sortie::mission {

// A position on the WGS-84 ellipsoid in decimal degrees. Radians exist only at the HCI boundary.
struct GeoPoint
{
    double latitude = 0.0;   // degrees, -90..90
    double longitude = 0.0;  // degrees, -180..180

    bool isValid() const
    {
        return std::isfinite(latitude) && std::isfinite(longitude) && latitude >= -90.0 && latitude <= 90.0
            && longitude >= -180.0 && longitude <= 180.0;
    }
    bool operator==(const GeoPoint &) const = default;
};

// Bounding box in degrees. When the box crosses the antimeridian, west > east.
struct GeoBox
{
    double south = 0.0, west = 0.0, north = 0.0, east = 0.0;
    bool empty = true;

    bool crossesAntimeridian() const { return !empty && west > east; }
    bool operator==(const GeoBox &) const = default;
};

} // namespace sortie::mission
