// The operator's rasters (core/raster): the input is a file in GDAL's /vsimem/ (a GeoTIFF in the
// seeds; GDAL picks the driver), opened as a DEM raster, as a folder's indexed DEM and as an
// orthophoto. Our code is what is checked: a raster it accepts has a finite WGS-84 box, every sample
// inside or around it is a finite height or NoData (never Pending), a tile has the size asked for,
// and a refusal names the file. Degenerate geotransforms (zero or non-finite, 0×0) must be refused and
// huge claimed sizes must not allocate (pixels are read in bounded chunks).
#include "DemRaster.h"
#include "IndexedDemSource.h"
#include "OrthophotoRenderer.h"

#include <QLoggingCategory>
#include <QString>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

using namespace sortie;
using namespace sortie::raster;

namespace {

const QString kPath = QStringLiteral("/vsimem/fuzz.tif");

void checkSample(const terrain::ElevationSample &s)
{
    if (s.status == terrain::SampleStatus::Pending)
        std::abort();
    if (s.hasValue() && !std::isfinite(s.ground))
        std::abort();
}

void checkRefusal(const QString &error)
{
    if (!error.startsWith(kPath))
        std::abort();
}

// Points across a box and just outside it, at fractions taken from the input.
template<typename Sample>
void sampleAround(const GeoBox &box, const uint8_t *data, size_t size, Sample sample)
{
    if (!std::isfinite(box.south) || !std::isfinite(box.north) || !std::isfinite(box.west) || !std::isfinite(box.east)
        || box.south > box.north || box.west > box.east)
        std::abort();
    const double fractions[] = {-0.01, 0.0, 0.5, 1.0, 1.01};
    for (double fy : fractions)
        for (double fx : fractions)
            sample(box.south + fy * (box.north - box.south), box.west + fx * (box.east - box.west));
    for (size_t k = 0; k + 1 < size && k < 32; k += 2)
        sample(box.south + data[k] / 255.0 * (box.north - box.south), box.west + data[k + 1] / 255.0 * (box.east - box.west));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const bool quiet = [] {
        CPLSetErrorHandler(CPLQuietErrorHandler);
        QLoggingCategory::setFilterRules(QStringLiteral("sortie.raster.info=false"));  // a line per run otherwise
        CPLSetConfigOption("GDAL_CACHEMAX", "64");  // MB: a run must not grow GDAL's cache without bound
        return true;
    }();
    (void)quiet;
    // Not copied: GDAL reads the fuzzer's buffer in place, and the file is gone when the run ends.
    VSILFILE *file = VSIFileFromMemBuffer(kPath.toUtf8().constData(), const_cast<GByte *>(data), vsi_l_offset(size), FALSE);
    if (!file)
        return 0;
    VSIFCloseL(file);

    QString error;
    if (auto dem = DemRaster::open(kPath, &error, 4)) {
        if (dem->width() < 1 || dem->height() < 1)
            std::abort();
        sampleAround(dem->box(), data, size, [&](double lat, double lon) {
            checkSample(dem->sample(lat, lon));
            if (dem->cachedChunks() > 4)
                std::abort();
        });
        checkSample(dem->sample(NAN, 0));
    } else {
        checkRefusal(error);
    }

    error.clear();
    if (auto folder = IndexedDemSource::open(kPath, {kPath}, &error, 1)) {
        if (folder->indexedCount() != 1 || folder->openCount() != 0)
            std::abort();
        checkSample(folder->sample({0.0, 0.0}));
        if (folder->openCount() > 1)
            std::abort();
    } else {
        checkRefusal(error);
    }

    error.clear();
    if (auto photo = OrthophotoRenderer::open(kPath, &error)) {
        // The tile holding the middle of the footprint, at a zoom the input picks (0..18).
        const double lat = std::clamp((photo->south() + photo->north()) / 2, -85.0, 85.0);
        const double lon = std::clamp((photo->west() + photo->east()) / 2, -180.0, 179.999);
        const int z = size > 0 ? data[size - 1] % 19 : 0;
        const double n = double(1 << z);
        const double s = std::sin(lat * M_PI / 180);
        const int x = std::clamp(int((lon + 180) / 360 * n), 0, (1 << z) - 1);
        const int y = std::clamp(int((0.5 - std::log((1 + s) / (1 - s)) / (4 * M_PI)) * n), 0, (1 << z) - 1);
        const RgbaTile tile = photo->render(z, x, y, 32, &error);
        if (tile.size != 32 || tile.rgba.size() != size_t(32 * 32 * 4))
            std::abort();
        if (!photo->render(z, x, y, 0, &error).rgba.empty() || !photo->render(z, x, y, 1 << 20, &error).rgba.empty())
            std::abort();
    } else {
        checkRefusal(error);
    }
    VSIUnlink(kPath.toUtf8().constData());
    return 0;
}
