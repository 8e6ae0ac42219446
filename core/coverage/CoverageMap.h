#pragma once

#include "Camera.h"

#include <QJsonObject>
#include <QString>

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace sortie::coverage {

// One photo where it was taken: the camera's position, its height above the ground beneath it and
// the direction the image's top faces (the vehicle's course for a camera fixed forward, looking
// straight down). A value not known is NaN, never 0.
struct Shot
{
    QString name;           // the photo's file name, for messages
    double latitude = 0;    // degrees, WGS-84
    double longitude = 0;   // degrees
    double heightAboveGround = std::numeric_limits<double>::quiet_NaN(); // m
    double headingDegrees = std::numeric_limits<double>::quiet_NaN();    // clockwise from true north
};

struct CoverageOptions
{
    mission::Camera camera;
    double cellMeters = 0;  // the raster's cell; 0: a 200th of the mean footprint's width, at least 0.1 m
    int minImages = 5;      // a ground point seen by fewer images is a hole (photogrammetry's rule of thumb)
    double minHoleArea = 10; // m²: smaller holes are not listed
};

// A percentile summary; absent when there was nothing to measure.
struct Spread
{
    double p5 = 0, p50 = 0, p95 = 0, min = 0, max = 0;
    int count = 0;
};

struct Hole
{
    double areaSquareMeters = 0;
    double centreLatitude = 0, centreLongitude = 0;
    std::vector<std::pair<double, double>> ring; // (longitude, latitude), closed, outer boundary
    // What to fly to fill it: the hole's convex hull grown by a quarter footprint's width (the
    // margin a scan's own edge sees poorly), (longitude, latitude), closed.
    std::vector<std::pair<double, double>> scanRing;
};

struct Unplaced
{
    QString file;
    QString reason; // translated
};

// The overlap a set of photos achieved over the ground they were meant to cover (the convex hull of
// their centres; a strip half a footprint wide when they are in one line): how many images see each
// cell, holes where fewer than `minImages` do, forward and side overlap between neighbouring
// photos, and the ground sample distance.
struct CoverageReport
{
    int photos = 0;                 // given
    int placed = 0;                 // with a footprint
    std::vector<Unplaced> unplaced;
    QString crs;                    // the raster's: "EPSG:32635" (UTM of the photos' centre)
    double cellMeters = 0;
    int minImages = 0;
    double areaSquareMeters = 0;    // the area judged
    double coveredFraction = 0;     // of it, seen by at least minImages images
    std::optional<Spread> imagesPerPoint;  // over the area's cells
    std::optional<Spread> forwardOverlap;  // % between successive photos of a leg
    std::optional<Spread> sideOverlap;     // % with the nearest photo of the neighbouring leg
    std::optional<Spread> gsdCm;           // ground sample distance, the coarser axis
    std::optional<Spread> heightAboveGround; // m, of the photos placed
    std::optional<double> legBearing;      // the legs' direction, 0 to 180° from north, from the forward pairs
    std::vector<Hole> holes;               // largest first
    QJsonObject toJson() const;
};

// The images-per-cell raster behind a report, in the report's CRS: row 0 is the north edge.
struct CoverageRaster
{
    int epsg = 0;
    double originEast = 0, originNorth = 0; // the north-west corner
    double cellMeters = 0;
    int width = 0, height = 0;
    std::vector<uint16_t> images; // width × height, row-major
};

// Footprints of every placeable shot (NaN height or heading: unplaced, with the reason), counted
// per cell with GDAL's rasteriser, the holes traced with GDAL's polygoniser. nullopt with *error
// when nothing can be judged (a camera without optics, no shot placed, a raster too large for the
// cell asked).
std::optional<CoverageReport> computeCoverage(const std::vector<Shot> &shots, const CoverageOptions &options,
                                              CoverageRaster *raster, QString *error);

// The raster as a one-band UInt16 GeoTIFF (deflate), written beside its name and renamed into place.
bool writeCoverageGeoTiff(const CoverageRaster &raster, const QString &path, QString *error);

} // namespace sortie::coverage
