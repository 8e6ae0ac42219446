#include "RasterFootprint.h"

#include <QCoreApplication>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>

namespace sortie::raster {

QString geoTransformProblem(const double toWorld[6], int width, int height)
{
    if (width < 1 || height < 1)
        return QCoreApplication::translate("RasterFootprint", "the raster has no pixels (%1×%2)").arg(width).arg(height);
    for (int i = 0; i < 6; ++i)
        if (!std::isfinite(toWorld[i]))
            return QCoreApplication::translate("RasterFootprint", "the raster's geotransform is not finite");
    double inverse[6];
    // GDAL refuses a determinant near zero (a zero pixel size); a tiny one still gives huge pixel numbers.
    if (!GDALInvGeoTransform(const_cast<double *>(toWorld), inverse))
        return QCoreApplication::translate("RasterFootprint", "the raster's geotransform cannot be inverted (a zero pixel size?)");
    for (double v : inverse)
        if (!std::isfinite(v))
            return QCoreApplication::translate("RasterFootprint", "the raster's geotransform cannot be inverted (a zero pixel size?)");
    return {};
}

void cornerBounds(const double toWorld[6], int width, int height, double bounds[4])
{
    double xs[4], ys[4];
    const int cols[4] = {0, width, 0, width}, rows[4] = {0, 0, height, height};
    for (int i = 0; i < 4; ++i) {
        xs[i] = toWorld[0] + toWorld[1] * cols[i] + toWorld[2] * rows[i];
        ys[i] = toWorld[3] + toWorld[4] * cols[i] + toWorld[5] * rows[i];
    }
    bounds[0] = *std::min_element(xs, xs + 4), bounds[2] = *std::max_element(xs, xs + 4);
    bounds[1] = *std::min_element(ys, ys + 4), bounds[3] = *std::max_element(ys, ys + 4);
}

bool boundsArePlaceable(const double bounds[4])
{
    constexpr double kFarthest = 1e9, kThinnest = 1e-9;
    for (int i = 0; i < 4; ++i)
        if (!std::isfinite(bounds[i]) || std::abs(bounds[i]) > kFarthest)
            return false;
    for (int axis = 0; axis < 2; ++axis) {
        const double low = bounds[axis], high = bounds[axis + 2];
        if (high - low < kThinnest * std::max({1.0, std::abs(low), std::abs(high)}))
            return false;
    }
    return true;
}

std::optional<GeoBox> footprintInWgs84(const double toWorld[6], int width, int height, OGRCoordinateTransformation *toWgs84)
{
    double b[4];
    cornerBounds(toWorld, width, height, b);
    if (!boundsArePlaceable(b))
        return std::nullopt;
    const double minX = b[0], minY = b[1], maxX = b[2], maxY = b[3];
    GeoBox box;
    if (!toWgs84) {
        box = {minY, minX, maxY, maxX};
    } else if (!toWgs84->TransformBounds(minX, minY, maxX, maxY, &box.west, &box.south, &box.east, &box.north, 21)) {
        return std::nullopt;
    }
    if (!std::isfinite(box.south) || !std::isfinite(box.west) || !std::isfinite(box.north) || !std::isfinite(box.east))
        return std::nullopt;
    return box;
}

} // namespace sortie::raster
