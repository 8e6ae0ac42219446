#include "DemRaster.h"

#include "Egm96Geoid.h"
#include "RasterLog.h"

#include <QCoreApplication>
#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>

namespace sortie::raster {

using terrain::ElevationSample;

namespace {
void destroyTransform(OGRCoordinateTransformation *t)
{
    OGRCoordinateTransformation::DestroyCT(t);
}
} // namespace

DemRaster::~DemRaster() = default;

std::unique_ptr<DemRaster> DemRaster::open(const QString &path, QString *error, int maxChunks, bool logDatum)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, why);
        return nullptr;
    };
    GdalDatasetPtr dataset = openRaster(path, error);
    if (!dataset)
        return nullptr;
    std::unique_ptr<DemRaster> r(new DemRaster);
    r->m_path = path;
    r->m_maxChunks = std::max(4, maxChunks);
    r->m_band = dataset->GetRasterBand(1);
    r->m_width = dataset->GetRasterXSize();
    r->m_height = dataset->GetRasterYSize();
    double toWorld[6];
    if (dataset->GetGeoTransform(toWorld) != CE_None)
        return fail(QCoreApplication::translate("DemRaster", "the raster is not georeferenced (no geotransform)"));
    if (const QString problem = geoTransformProblem(toWorld, r->m_width, r->m_height); !problem.isEmpty())
        return fail(problem);
    if (!GDALInvGeoTransform(toWorld, r->m_toPixel))
        return fail(QCoreApplication::translate("RasterFootprint", "the raster's geotransform cannot be inverted (a zero pixel size?)"));
    const OGRSpatialReference *srs = dataset->GetSpatialRef();
    if (!srs || srs->IsEmpty())
        return fail(QCoreApplication::translate("DemRaster", "the raster states no coordinate reference system"));
    OGRSpatialReference wgs84;
    wgs84.importFromEPSG(4326);
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // x = longitude, y = latitude
    OGRSpatialReference target(*srs);
    target.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    CPLErrorReset();
    std::unique_ptr<OGRCoordinateTransformation, void (*)(OGRCoordinateTransformation *)> back{nullptr, destroyTransform};
    // Degrees on the WGS-84 datum need no transformation: the common case (.hgt, Copernicus) stays cheap.
    if (!(target.IsGeographic() && target.IsSameGeogCS(&wgs84))) {
        r->m_fromWgs84 = {OGRCreateCoordinateTransformation(&wgs84, &target), destroyTransform};
        back.reset(OGRCreateCoordinateTransformation(&target, &wgs84));
        if (!r->m_fromWgs84 || !back)
            return fail(QCoreApplication::translate("DemRaster", "no transformation from WGS-84 into the raster's CRS: %1")
                            .arg(lastGdalError(QCoreApplication::translate("DemRaster", "PROJ gave no reason"))));
    }
    const std::optional<GeoBox> box = footprintInWgs84(toWorld, r->m_width, r->m_height, back.get());
    if (!box)
        return fail(QCoreApplication::translate("DemRaster", "the raster's extent cannot be expressed in WGS-84 degrees"));
    r->m_box = *box;
    int hasNoData = 0;
    const double noData = r->m_band->GetNoDataValue(&hasNoData);
    if (hasNoData)
        r->m_noData = noData;
    r->m_datum = VerticalDatum::of(srs);
    switch (r->m_datum.kind) {
    case VerticalDatum::Kind::Ellipsoidal: {
        QString geoidError;
        r->m_geoid = datum::Egm96Geoid::open(datum::Egm96Geoid::defaultGridPath(), &geoidError);
        if (!r->m_geoid)
            return fail(QCoreApplication::translate("DemRaster", "its heights are ellipsoidal and converting them to AMSL needs the EGM96 geoid: %1").arg(geoidError));
        if (logDatum)
            qCInfo(lcRaster).noquote() << path << "heights are" << r->m_datum.describe() << "- converted to AMSL through EGM96";
        break;
    }
    case VerticalDatum::Kind::Orthometric:
        if (logDatum)
            qCInfo(lcRaster).noquote() << path << "heights are" << r->m_datum.describe() << "- taken as AMSL";
        break;
    case VerticalDatum::Kind::Unstated:
        if (logDatum)
            qCInfo(lcRaster).noquote() << path << "states no vertical datum - heights taken as AMSL (EGM96)";
        break;
    }
    r->m_dataset = std::move(dataset);
    return r;
}

bool DemRaster::mayCover(double latitude, double longitude) const
{
    return m_box.contains(latitude, longitude);
}

const std::vector<float> *DemRaster::chunk(int chunkColumn, int chunkRow)
{
    // 64 bits: a header may claim 2³¹ pixels a side (nothing is allocated for that: chunks are read as needed).
    const qint64 key = qint64(chunkRow) * ((qint64(m_width) + kChunk - 1) / kChunk) + chunkColumn;
    if (auto found = m_chunks.find(key); found != m_chunks.end()) {
        m_recent.splice(m_recent.begin(), m_recent, found->second.place);
        return &found->second.heights;
    }
    const int x0 = chunkColumn * kChunk, y0 = chunkRow * kChunk;
    const int w = std::min(kChunk, m_width - x0), h = std::min(kChunk, m_height - y0);
    std::vector<float> heights(size_t(w) * size_t(h));
    CPLErrorReset();
    if (m_band->RasterIO(GF_Read, x0, y0, w, h, heights.data(), w, h, GDT_Float32, 0, 0) != CE_None) {
        qCWarning(lcRaster).noquote() << m_path << "cannot be read at pixel" << x0 << y0 << ":" << lastGdalError(QStringLiteral("read failed"));
        return nullptr;
    }
    ++m_chunkReads;
    if (m_noData) {
        const float nd = float(*m_noData);
        for (float &v : heights)
            if (v == nd)
                v = std::nanf("");
    }
    if (int(m_chunks.size()) >= m_maxChunks) {
        m_chunks.erase(m_recent.back());
        m_recent.pop_back();
    }
    m_recent.push_front(key);
    Chunk &stored = m_chunks[key];
    stored.heights = std::move(heights);
    stored.place = m_recent.begin();
    return &stored.heights;
}

std::optional<float> DemRaster::pixel(int column, int row)
{
    const std::vector<float> *c = chunk(column / kChunk, row / kChunk);
    if (!c)
        return std::nullopt;
    const int w = std::min(kChunk, m_width - (column / kChunk) * kChunk);
    return (*c)[size_t(row % kChunk) * size_t(w) + size_t(column % kChunk)];
}

ElevationSample DemRaster::sample(double latitude, double longitude)
{
    if (!std::isfinite(latitude) || !std::isfinite(longitude) || !mayCover(latitude, longitude))
        return ElevationSample::noData();
    double x = longitude, y = latitude;
    if (m_fromWgs84 && !m_fromWgs84->Transform(1, &x, &y))
        return ElevationSample::noData();
    // Pixel centres are the posts: pixel/line coordinates less half a pixel.
    double column = m_toPixel[0] + m_toPixel[1] * x + m_toPixel[2] * y - 0.5;
    double row = m_toPixel[3] + m_toPixel[4] * x + m_toPixel[5] * y - 0.5;
    if (!std::isfinite(column) || !std::isfinite(row))
        return ElevationSample::noData();  // PROJ gave no finite position
    // A point on a post (to rounding) is that post: a nodata pixel beside it has no weight.
    if (std::abs(column - std::round(column)) < 1e-6)
        column = std::round(column);
    if (std::abs(row - std::round(row)) < 1e-6)
        row = std::round(row);
    // The outer half pixel belongs to the edge pixel: held at the edge posts.
    if (column < -0.5 || row < -0.5 || column > m_width - 0.5 || row > m_height - 0.5)
        return ElevationSample::noData();
    column = std::clamp(column, 0.0, double(m_width - 1));
    row = std::clamp(row, 0.0, double(m_height - 1));
    const int c0 = std::min(int(std::floor(column)), std::max(0, m_width - 2));
    const int r0 = std::min(int(std::floor(row)), std::max(0, m_height - 2));
    const int c1 = std::min(c0 + 1, m_width - 1), r1 = std::min(r0 + 1, m_height - 1);
    const double fx = std::clamp(column - c0, 0.0, 1.0), fy = std::clamp(row - r0, 0.0, 1.0);
    const double w[4] = {(1 - fy) * (1 - fx), (1 - fy) * fx, fy * (1 - fx), fy * fx};
    const int cs[4] = {c0, c1, c0, c1}, rs[4] = {r0, r0, r1, r1};
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        if (w[i] == 0.0)
            continue;
        const std::optional<float> h = pixel(cs[i], rs[i]);
        if (!h || std::isnan(*h))
            return ElevationSample::noData();  // never interpolate across nodata
        sum += w[i] * double(*h);
    }
    if (m_geoid) {
        const std::optional<double> amsl = m_geoid->amslFromEllipsoidal(latitude, longitude, sum);
        return amsl ? ElevationSample::value(*amsl) : ElevationSample::noData();
    }
    return ElevationSample::value(sum);
}

} // namespace sortie::raster
