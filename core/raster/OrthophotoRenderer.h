#pragma once

#include "GdalDataset.h"

#include <QString>

#include <memory>
#include <mutex>
#include <vector>

namespace sortie::raster {

// One rendered map tile: size×size pixels, RGBA 8 bits each, not premultiplied, row 0 at the north.
struct RgbaTile
{
    int size = 0;
    std::vector<unsigned char> rgba;
    bool covered = false;  // false: the raster does not reach the tile (all transparent)
};

// A georeferenced image (an orthophoto: GeoTIFF, COG, JPEG2000, ... in any CRS, e.g. UTM) cut into
// Web Mercator (EPSG:3857) XYZ tiles on demand: each tile is warped from the raster with GDALWarp,
// which reads the overview whose resolution matches the tile's (-ovr AUTO), so a large raster
// stays fast when zoomed out. Pixels outside the raster, and where its nodata or alpha says so, are
// transparent. Grey, paletted, RGB and RGBA rasters of 8-bit samples are drawn; a tile that misses
// the raster's footprint is answered without reading it. Thread-safe (one render at a time: the
// GDAL dataset is not shared between threads); give each worker thread its own renderer for more.
class OrthophotoRenderer
{
public:
    static constexpr int kMaxZoom = 30;
    static constexpr int kMaxTileSize = 4096;

    // Null with an error naming the file and GDAL's reason when it cannot be drawn on the map.
    static std::unique_ptr<OrthophotoRenderer> open(const QString &path, QString *error);
    ~OrthophotoRenderer();

    QString path() const { return m_path; }
    int overviewCount() const { return m_overviews; }
    // The WGS-84 box of the raster's footprint, degrees.
    double south() const { return m_south; }
    double west() const { return m_west; }
    double north() const { return m_north; }
    double east() const { return m_east; }
    // Whether the XYZ tile z/x/y may show part of the raster.
    bool touches(int z, int x, int y) const;
    // The XYZ tile z/x/y (x east from the antimeridian, y south from the top); an empty (all
    // transparent) tile outside the footprint; `error` set when GDAL fails to warp it. A size outside
    // 1..kMaxTileSize gives an empty tile (size 0) and an error.
    RgbaTile render(int z, int x, int y, int size = 256, QString *error = nullptr);

private:
    OrthophotoRenderer() = default;
    void toRgba(const std::vector<unsigned char> &bands, int size, RgbaTile &tile) const;

    QString m_path;
    GdalDatasetPtr m_dataset;
    std::mutex m_mutex;
    int m_colorBands = 0;  // bands warped besides alpha: 1 (grey or paletted) or 3 (RGB)
    bool m_paletted = false;
    std::vector<unsigned char> m_palette;  // RGBA per index when paletted
    int m_overviews = 0;
    double m_minX = 0, m_minY = 0, m_maxX = 0, m_maxY = 0;  // footprint, EPSG:3857 metres
    bool m_bounded = false;
    double m_south = 0, m_west = 0, m_north = 0, m_east = 0;
};

} // namespace sortie::raster
