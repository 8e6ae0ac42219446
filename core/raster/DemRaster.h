#pragma once

#include "ElevationSample.h"
#include "GdalDataset.h"
#include "RasterFootprint.h"
#include "VerticalDatum.h"

#include <QString>

#include <list>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

class GDALRasterBand;
class OGRCoordinateTransformation;

namespace sortie::datum {
class Egm96Geoid;
}

namespace sortie::raster {

// One elevation raster GDAL reads (GeoTIFF, COG, .hgt, DTED, a VRT...), in any horizontal CRS:
// a WGS-84 point is transformed into the raster's CRS (PROJ through OGR) and the height is
// interpolated bilinearly between the four pixel centres around it, as HgtTile does between posts.
// A nodata pixel with weight makes the sample NoData (never 0 m). Heights are returned above mean
// sea level: ellipsoidal ones are converted through the EGM96 geoid, orthometric ones (EGM96,
// EGM2008, a national datum) and unstated ones are taken as they are. Pixels are read on demand in
// chunks of kChunk×kChunk, of which at most `maxChunks` stay cached (least recently used goes).
class DemRaster
{
public:
    static constexpr int kChunk = 256;
    static constexpr int kDefaultMaxChunks = 64;  // 16 MiB of float heights per raster

    // Null with an error naming the file (and GDAL's or PROJ's reason) when it cannot be used. The
    // vertical datum is logged unless `logDatum` is false (a file opened again after being closed).
    static std::unique_ptr<DemRaster> open(const QString &path, QString *error, int maxChunks = kDefaultMaxChunks, bool logDatum = true);
    ~DemRaster();

    QString path() const { return m_path; }
    const VerticalDatum &verticalDatum() const { return m_datum; }
    int width() const { return m_width; }
    int height() const { return m_height; }
    // The WGS-84 box the raster covers (degrees), for quick rejection.
    const GeoBox &box() const { return m_box; }
    bool mayCover(double latitude, double longitude) const;
    terrain::ElevationSample sample(double latitude, double longitude);
    // Chunks read from the file so far (cache misses), for tests and benchmarks.
    long chunkReads() const { return m_chunkReads; }
    int cachedChunks() const { return int(m_chunks.size()); }

private:
    DemRaster() = default;
    // The height at pixel (column, row), NaN for nodata; nullopt when the read fails.
    std::optional<float> pixel(int column, int row);
    const std::vector<float> *chunk(int chunkColumn, int chunkRow);

    QString m_path;
    GdalDatasetPtr m_dataset;
    GDALRasterBand *m_band = nullptr;
    int m_width = 0, m_height = 0;
    double m_toPixel[6] = {};  // inverse geotransform: raster CRS -> pixel/line
    std::unique_ptr<OGRCoordinateTransformation, void (*)(OGRCoordinateTransformation *)> m_fromWgs84{nullptr, nullptr};
    GeoBox m_box;
    std::optional<double> m_noData;
    VerticalDatum m_datum;
    std::unique_ptr<datum::Egm96Geoid> m_geoid;  // only for ellipsoidal heights
    int m_maxChunks = kDefaultMaxChunks;
    std::list<qint64> m_recent;  // chunk keys, most recent first
    struct Chunk
    {
        std::vector<float> heights;
        std::list<qint64>::iterator place;
    };
    std::unordered_map<qint64, Chunk> m_chunks;
    long m_chunkReads = 0;
};

} // namespace sortie::raster
