// Raster benchmark (core/raster): DEM sampling along a 100 km path from the same 1″ SRTM tiles
// read by the hand-written .hgt reader and by GDAL, and from GeoTIFFs (EPSG:4326 and UTM); then
// Web Mercator tiles cut from a large UTM orthophoto with and without overviews. Prints each
// figure (docs/performance.md keeps them); DEM sampling has a target, exits 1 if it is missed.
// Run: build/tests/raster/bench_raster
#include "BenchClock.h"
#include "DemOpener.h"
#include "GdalDemSource.h"
#include "GeoTiffWriter.h"
#include "HgtTile.h"
#include "HgtTileSource.h"
#include "HgtWriter.h"
#include "OrthophotoRenderer.h"
#include "PathSampling.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QTemporaryDir>

#include <cmath>
#include <cstdio>
#include <memory>
#include <thread>
#include <utility>
#include <vector>

using namespace sortie;
using namespace sortie::raster;
using sortie::test::judge;
using sortie::test::loadAverage;
using sortie::test::median;
using sortie::test::Timing;

namespace {

bool report(const char *what, Timing t, double targetMs)
{
    const auto verdict = judge(t, targetMs);
    std::printf("%-60s %9.3f ms wall %9.3f ms cpu", what, t.wallMs, t.cpuMs);
    if (targetMs > 0)
        std::printf("   (target < %g ms)%s", targetMs, verdict.note);
    std::printf("\n");
    return verdict.met;
}

double hills(double lat, double lon)
{
    return 150 + 80 * std::sin(lat * 40) * std::cos(lon * 25) + 30 * std::sin(lon * 170 + lat * 90);
}

// Samples every point of the path; returns how many had a value.
int sampleAll(terrain::ElevationSource &source, const terrain::SampledPath &path)
{
    int values = 0;
    for (const auto &p : path.points)
        values += source.sample(p.position).hasValue() ? 1 : 0;
    return values;
}

// File descriptors the process holds now (each open GeoTIFF holds one).
int openDescriptors()
{
    return int(QDir(QStringLiteral("/proc/self/fd")).entryList(QDir::Files | QDir::System).size());
}

// A folder of 1,000 small GeoTIFF tiles (40 × 25 tiles of 0.1°, 100² pixels each, over 24..28 E,
// 55..57.5 N), as a national DEM is delivered: time to the first height, and a path across it.
bool benchTileFolder(const QDir &parent)
{
    const QString folder = parent.filePath(QStringLiteral("tiles"));
    QDir().mkpath(folder);
    QElapsedTimer setup;
    setup.start();
    for (int row = 0; row < 25; ++row)
        for (int col = 0; col < 40; ++col) {
            raster::test::GeoTiffSpec tile;
            tile.width = tile.height = 100;
            const double west = 24.0 + col * 0.1, north = 57.5 - row * 0.1;
            const double gt[6] = {west, 0.001, 0, north, 0, -0.001};
            std::copy(gt, gt + 6, tile.geoTransform);
            const QString name = QStringLiteral("tile_%1_%2.tif").arg(row, 2, 10, QLatin1Char('0')).arg(col, 2, 10, QLatin1Char('0'));
            if (!raster::test::writeGeoTiff(folder + QLatin1Char('/') + name, tile, [&](int, int r, int c) {
                    return hills(north - (r + 0.5) * 0.001, west + (c + 0.5) * 0.001);
                }))
                return false;
        }
    std::printf("%-60s %9.0f ms\n", "(setup: 1,000 GeoTIFF tiles of 100² pixels)", double(setup.elapsed()));
    const int descriptorsBefore = openDescriptors();
    std::unique_ptr<terrain::ElevationSource> dem;
    QString error;
    bool ok = true;
    report("folder of 1,000 GeoTIFF tiles: open, time to first height", median(3, [&] {
               dem.reset();
               dem = openDem(folder, &error);
               ok = ok && dem && dem->sample({56.25, 26.05}).hasValue();
           }), 0);
    if (!ok)
        return std::fprintf(stderr, "the tile folder gave no height: %s\n", qPrintable(error)), false;
    std::printf("%-60s %9d\n", "  file descriptors held after the first height", openDescriptors() - descriptorsBefore);
    // 230 km from one corner of the tiles to the other, crossing ~60 of them.
    const terrain::SampledPath path = terrain::samplePath({{55.05, 24.05}, {57.45, 27.95}}, 30);
    int values = 0;
    report("folder of 1,000 tiles: 230 km path, first pass", median(1, [&] { values = sampleAll(*dem, path); }), 0);
    std::printf("%-60s %9d of %zu\n", "  samples with a value", values, path.points.size());
    report("folder of 1,000 tiles: 230 km path, warm", median(5, [&] { sampleAll(*dem, path); }), 0);
    std::printf("%-60s %9d\n", "  file descriptors held after the path", openDescriptors() - descriptorsBefore);
    return values == int(path.points.size());
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    bool ok = true;
    std::printf("Sortie raster benchmark (median of repeated runs; load average %.2f on %u cores)\n", loadAverage(),
                std::thread::hardware_concurrency());
    QTemporaryDir dir;
    QElapsedTimer setup;
    setup.start();
    // Two 1″ SRTM tiles, and the same ground as one tiled GeoTIFF in degrees and one in UTM 35N.
    for (int west : {24, 25})
        if (!terrain::test::writeHgt(dir.filePath(terrain::hgtName({56, west})), 3601, [west](int r, int c) {
                return int(hills(57 - r / 3600.0, west + c / 3600.0));
            }))
            return 1;
    raster::test::GeoTiffSpec wgs;
    wgs.width = 7200, wgs.height = 3600;
    const double gtWgs[6] = {24.0, 1 / 3600.0, 0, 57.0, 0, -1 / 3600.0};
    std::copy(gtWgs, gtWgs + 6, wgs.geoTransform);
    wgs.tiled = true;
    const QString wgsPath = dir.filePath(QStringLiteral("dem-4326.tif"));
    if (!raster::test::writeGeoTiff(wgsPath, wgs, [](int, int r, int c) { return hills(57 - (r + 0.5) / 3600.0, 24 + (c + 0.5) / 3600.0); }))
        return 1;
    raster::test::GeoTiffSpec utm;
    utm.width = 6000, utm.height = 6000;  // 30 m pixels: 180 km, the whole path
    const double gtUtm[6] = {250000, 30, 0, 6320000, 0, -30};
    std::copy(gtUtm, gtUtm + 6, utm.geoTransform);
    utm.crs = QStringLiteral("EPSG:32635");
    utm.tiled = true;
    const QString utmPath = dir.filePath(QStringLiteral("dem-utm.tif"));
    if (!raster::test::writeGeoTiff(utmPath, utm, [](int, int r, int c) { return 100 + 0.01 * r + 0.02 * c; }))
        return 1;
    std::printf("%-60s %9.0f ms\n", "(setup: writing the rasters)", double(setup.elapsed()));

    // 100 km at a 30 m step across both tiles.
    const terrain::SampledPath path = terrain::samplePath({{56.20, 24.20}, {56.50, 24.90}, {56.78, 25.55}}, 30);
    std::printf("%-60s %9zu samples over %.1f km\n", "path", path.points.size(), path.length() / 1000);

    QString error;
    {
        terrain::HgtTileSource tiles(dir.path());
        int values = 0;
        report("hand-written .hgt reader: first pass (maps and checks 2 tiles)", median(1, [&] { values = sampleAll(tiles, path); }), 0);
        std::printf("%-60s %9d of %zu\n", "  samples with a value", values, path.points.size());
        ok &= report("hand-written .hgt reader: 100 km path", median(21, [&] { sampleAll(tiles, path); }), 20);
    }
    {
        auto gdal = GdalDemSource::open(dir.path(), {dir.filePath(terrain::hgtName({56, 24})), dir.filePath(terrain::hgtName({56, 25}))}, &error);
        if (!gdal)
            return std::fprintf(stderr, "%s\n", qPrintable(error)), 1;
        report("GDAL (SRTMHGT driver) .hgt: first pass (reads chunks)", median(1, [&] { sampleAll(*gdal, path); }), 0);
        ok &= report("GDAL (SRTMHGT driver) .hgt: 100 km path", median(21, [&] { sampleAll(*gdal, path); }), 20);
    }
    {
        auto tif = openDem(wgsPath, &error);
        if (!tif)
            return std::fprintf(stderr, "%s\n", qPrintable(error)), 1;
        report("GDAL GeoTIFF EPSG:4326 (256² tiles): first pass", median(1, [&] { sampleAll(*tif, path); }), 0);
        ok &= report("GDAL GeoTIFF EPSG:4326: 100 km path", median(21, [&] { sampleAll(*tif, path); }), 20);
    }
    {
        auto tif = openDem(utmPath, &error);
        if (!tif)
            return std::fprintf(stderr, "%s\n", qPrintable(error)), 1;
        int values = 0;
        report("GDAL GeoTIFF UTM 35N (PROJ per point): first pass", median(1, [&] { values = sampleAll(*tif, path); }), 0);
        std::printf("%-60s %9d of %zu\n", "  samples with a value", values, path.points.size());
        ok &= report("GDAL GeoTIFF UTM 35N: 100 km path", median(21, [&] { sampleAll(*tif, path); }), 40);
    }

    if (!benchTileFolder(QDir(dir.path())))
        return 1;

    // A large orthophoto: 8192² RGB pixels of 0.5 m in UTM 35N (4 km), tiled, with and without overviews.
    for (bool overviews : {false, true}) {
        raster::test::GeoTiffSpec photo;
        photo.width = photo.height = 8192;
        const double gt[6] = {310000, 0.5, 0, 6320000, 0, -0.5};
        std::copy(gt, gt + 6, photo.geoTransform);
        photo.crs = QStringLiteral("EPSG:32635");
        photo.bands = 3;
        photo.type = GDT_Byte;
        photo.tiled = true;
        if (overviews)
            photo.overviews = {2, 4, 8, 16, 32};
        const QString photoPath = dir.filePath(overviews ? QStringLiteral("photo-ovr.tif") : QStringLiteral("photo.tif"));
        setup.restart();
        if (!raster::test::writeGeoTiff(photoPath, photo, [](int b, int r, int c) { return double((r * (b + 1) + c * 3) & 0xff); }))
            return 1;
        std::printf("%-60s %9.0f ms\n", overviews ? "(setup: 8192² orthophoto with 5 overviews)" : "(setup: 8192² orthophoto)", double(setup.elapsed()));
        auto renderer = OrthophotoRenderer::open(photoPath, &error);
        if (!renderer)
            return std::fprintf(stderr, "%s\n", qPrintable(error)), 1;
        const double lat = (renderer->north() + renderer->south()) / 2, lon = (renderer->west() + renderer->east()) / 2;
        for (int z : {11, 12, 13, 14, 15, 16, 17, 18}) {
            // The tiles of the image nearest its middle, as a screen asks for them (up to 9).
            const double n = 1 << z;
            const double cx = (lon + 180) / 360 * n;
            const double s = std::sin(lat * M_PI / 180);
            const double cy = (0.5 - std::log((1 + s) / (1 - s)) / (4 * M_PI)) * n;
            std::vector<std::pair<int, int>> keys;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    if (renderer->touches(z, int(cx) + dx, int(cy) + dy))
                        keys.emplace_back(int(cx) + dx, int(cy) + dy);
            int i = 0, covered = 0;
            const Timing t = median(9, [&] {
                const auto [x, y] = keys[size_t(i++) % keys.size()];
                covered += renderer->render(z, x, y, 256, &error).covered ? 1 : 0;
            });
            char what[96];
            std::snprintf(what, sizeof what, "orthophoto tile z%d (%zu tile(s) of it), %s", z, keys.size(),
                          overviews ? "with overviews" : "no overviews");
            report(what, t, 0);
            if (covered != 9)
                return std::fprintf(stderr, "a tile of the image came out empty\n"), 1;
        }
    }
    return ok ? 0 : 1;
}
