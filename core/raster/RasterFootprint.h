#pragma once

#include <QString>

#include <optional>

class OGRCoordinateTransformation;

namespace sortie::raster {

// A box in WGS-84 degrees (longitude west..east, latitude south..north).
struct GeoBox
{
    double south = 0, west = 0, north = 0, east = 0;

    // A hair of slack for rounding at the edges (TransformBounds densifies, so the box holds the extent).
    bool contains(double latitude, double longitude) const
    {
        constexpr double slack = 1e-9;
        return latitude >= south - slack && latitude <= north + slack && longitude >= west - slack && longitude <= east + slack;
    }
};

// Why a raster's size and geotransform cannot place its pixels (a translated sentence), or empty when
// they can: every coefficient finite, an invertible transform (no zero pixel size), at least one pixel.
// Rotated and negative-size transforms are valid.
QString geoTransformProblem(const double toWorld[6], int width, int height);

// The box holding the raster's four corners in its own CRS: minX, minY, maxX, maxY.
void cornerBounds(const double toWorld[6], int width, int height, double bounds[4]);

// Whether a box from cornerBounds can be handed to PROJ: finite, within ±1e9 of the CRS's origin (no
// CRS on Earth reaches further) and not vanishingly thin for its magnitude. GDAL's TransformBounds
// steps along the edges in 21 parts and never ends when a step is below a coordinate's precision.
bool boundsArePlaceable(const double bounds[4]);

// The WGS-84 box holding a width×height raster whose geotransform is `toWorld` (all four corners, so a
// rotated raster is held too). `toWgs84` converts from the raster's CRS; null when that CRS is WGS-84
// degrees already. Nullopt when the corners cannot be converted.
std::optional<GeoBox> footprintInWgs84(const double toWorld[6], int width, int height, OGRCoordinateTransformation *toWgs84);

} // namespace sortie::raster
