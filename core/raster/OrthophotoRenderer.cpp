#include "OrthophotoRenderer.h"

#include "RasterFootprint.h"
#include "RasterLog.h"

#include <QCoreApplication>
#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal_priv.h>
#include <gdal_utils.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>

namespace sortie::raster {

namespace {

constexpr double kHalfWorld = 20037508.342789244;  // EPSG:3857's extent from the centre, metres

struct TransformDeleter
{
    void operator()(OGRCoordinateTransformation *t) const { OGRCoordinateTransformation::DestroyCT(t); }
};

// The raster's extent in `to`'s coordinates; false when it cannot be transformed.
bool extentIn(GDALDataset &dataset, const OGRSpatialReference &from, OGRSpatialReference to, double out[4])
{
    double gt[6];
    if (dataset.GetGeoTransform(gt) != CE_None)
        return false;
    double b[4];
    cornerBounds(gt, dataset.GetRasterXSize(), dataset.GetRasterYSize(), b);  // all four: a rotated image too
    if (!boundsArePlaceable(b))
        return false;
    const double minX = b[0], minY = b[1], maxX = b[2], maxY = b[3];
    OGRSpatialReference source(from);
    source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    to.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation, TransformDeleter> t(OGRCreateCoordinateTransformation(&source, &to));
    return t && t->TransformBounds(minX, minY, maxX, maxY, &out[0], &out[1], &out[2], &out[3], 21);
}

} // namespace

OrthophotoRenderer::~OrthophotoRenderer() = default;

std::unique_ptr<OrthophotoRenderer> OrthophotoRenderer::open(const QString &path, QString *error)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, why);
        return nullptr;
    };
    GdalDatasetPtr dataset = openRaster(path, error);
    if (!dataset)
        return nullptr;
    const OGRSpatialReference *srs = dataset->GetSpatialRef();
    double gt[6];
    if (!srs || srs->IsEmpty() || dataset->GetGeoTransform(gt) != CE_None)
        return fail(QCoreApplication::translate("OrthophotoRenderer", "the image is not georeferenced (no CRS or no geotransform)"));
    if (const QString problem = geoTransformProblem(gt, dataset->GetRasterXSize(), dataset->GetRasterYSize()); !problem.isEmpty())
        return fail(problem);
    std::unique_ptr<OrthophotoRenderer> r(new OrthophotoRenderer);
    r->m_path = path;
    const int count = dataset->GetRasterCount();
    GDALRasterBand *first = dataset->GetRasterBand(1);
    const bool lastIsAlpha = count > 1 && dataset->GetRasterBand(count)->GetColorInterpretation() == GCI_AlphaBand;
    const int colour = count - (lastIsAlpha ? 1 : 0);
    r->m_colorBands = colour >= 3 ? 3 : 1;
    r->m_overviews = first->GetOverviewCount();
    if (const GDALColorTable *table = first->GetColorTable(); table && r->m_colorBands == 1) {
        r->m_paletted = true;
        r->m_palette.assign(256 * 4, 0);
        for (int i = 0; i < std::min(256, table->GetColorEntryCount()); ++i) {
            const GDALColorEntry *e = table->GetColorEntry(i);
            const short c[4] = {e->c1, e->c2, e->c3, e->c4};
            for (int k = 0; k < 4; ++k)
                r->m_palette[size_t(i) * 4 + size_t(k)] = static_cast<unsigned char>(std::clamp<int>(c[k], 0, 255));
        }
    }
    OGRSpatialReference mercator, wgs84;
    mercator.importFromEPSG(3857);
    wgs84.importFromEPSG(4326);
    double box[4];
    if (extentIn(*dataset, *srs, mercator, box)) {
        r->m_minX = box[0], r->m_minY = box[1], r->m_maxX = box[2], r->m_maxY = box[3];
        r->m_bounded = true;
    }
    if (extentIn(*dataset, *srs, wgs84, box))
        r->m_west = box[0], r->m_south = box[1], r->m_east = box[2], r->m_north = box[3];
    else if (!r->m_bounded)
        return fail(QCoreApplication::translate("OrthophotoRenderer", "its extent cannot be placed on the map: %1").arg(lastGdalError(QCoreApplication::translate("OrthophotoRenderer", "PROJ gave no reason"))));
    qCInfo(lcRaster).noquote() << path << dataset->GetRasterXSize() << "x" << dataset->GetRasterYSize() << "pixels," << count
                               << "band(s)," << r->m_overviews << "overview(s)";
    r->m_dataset = std::move(dataset);
    return r;
}

bool OrthophotoRenderer::touches(int z, int x, int y) const
{
    if (z < 0 || z > kMaxZoom)
        return false;
    if (!m_bounded)
        return true;
    const double span = 2 * kHalfWorld / double(1 << z);
    const double minX = -kHalfWorld + x * span, maxX = minX + span;
    const double maxY = kHalfWorld - y * span, minY = maxY - span;
    return maxX > m_minX && minX < m_maxX && maxY > m_minY && minY < m_maxY;
}

RgbaTile OrthophotoRenderer::render(int z, int x, int y, int size, QString *error)
{
    RgbaTile tile;
    if (size < 1 || size > kMaxTileSize) {
        if (error)
            *error = QCoreApplication::translate("OrthophotoRenderer", "%1: tile size %2 is outside 1..%3").arg(m_path).arg(size).arg(kMaxTileSize);
        return tile;
    }
    tile.size = size;
    tile.rgba.assign(size_t(size) * size_t(size) * 4, 0);
    if (z < 0 || z > kMaxZoom || x < 0 || y < 0 || x >= (1 << z) || y >= (1 << z) || !touches(z, x, y))
        return tile;
    const std::lock_guard lock(m_mutex);
    GDALDriver *mem = GetGDALDriverManager()->GetDriverByName("MEM");
    const int bands = m_colorBands + 1;
    GdalDatasetPtr target(mem->Create("", size, size, bands, GDT_Byte, nullptr));
    if (!target) {
        if (error)
            *error = lastGdalError(QCoreApplication::translate("OrthophotoRenderer", "no memory for a tile"));
        return tile;
    }
    const double span = 2 * kHalfWorld / double(1 << z);
    double gt[6] = {-kHalfWorld + x * span, span / size, 0.0, kHalfWorld - y * span, 0.0, -span / size};
    target->SetGeoTransform(gt);
    OGRSpatialReference mercator;
    mercator.importFromEPSG(3857);
    target->SetSpatialRef(&mercator);
    target->GetRasterBand(bands)->SetColorInterpretation(GCI_AlphaBand);
    // Bilinear for imagery; a palette's indices are not numbers to blend.
    CPLStringList args;
    args.AddString("-r");
    args.AddString(m_paletted ? "near" : "bilinear");
    args.AddString("-dstalpha");
    args.AddString("-ovr");
    args.AddString("AUTO");
    GDALWarpAppOptions *options = GDALWarpAppOptionsNew(args.List(), nullptr);
    GDALDatasetH source = GDALDataset::ToHandle(m_dataset.get());
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    int usageError = 0;
    GDALDatasetH done = GDALWarp(nullptr, GDALDataset::ToHandle(target.get()), 1, &source, options, &usageError);
    CPLPopErrorHandler();
    GDALWarpAppOptionsFree(options);
    if (!done) {
        if (error)
            *error = QCoreApplication::translate("OrthophotoRenderer", "%1: tile %2/%3/%4: %5").arg(m_path).arg(z).arg(x).arg(y).arg(lastGdalError(QCoreApplication::translate("OrthophotoRenderer", "the warp failed")));
        return tile;
    }
    std::vector<unsigned char> pixels(size_t(size) * size_t(size) * size_t(bands));
    // Pixel-interleaved: each pixel's bands side by side.
    if (target->RasterIO(GF_Read, 0, 0, size, size, pixels.data(), size, size, GDT_Byte, bands, nullptr, bands, size_t(size) * bands, 1, nullptr)
        != CE_None) {
        if (error)
            *error = lastGdalError(QCoreApplication::translate("OrthophotoRenderer", "the warped tile cannot be read"));
        return tile;
    }
    toRgba(pixels, size, tile);
    return tile;
}

void OrthophotoRenderer::toRgba(const std::vector<unsigned char> &bands, int size, RgbaTile &tile) const
{
    const int stride = m_colorBands + 1;
    const size_t n = size_t(size) * size_t(size);
    for (size_t i = 0; i < n; ++i) {
        const unsigned char *p = &bands[i * size_t(stride)];
        unsigned char *out = &tile.rgba[i * 4];
        unsigned char alpha = p[m_colorBands];
        if (alpha == 0)
            continue;
        if (m_paletted) {
            const unsigned char *c = &m_palette[size_t(p[0]) * 4];
            out[0] = c[0], out[1] = c[1], out[2] = c[2];
            alpha = static_cast<unsigned char>(alpha * c[3] / 255);
        } else if (m_colorBands == 1) {
            out[0] = out[1] = out[2] = p[0];
        } else {
            out[0] = p[0], out[1] = p[1], out[2] = p[2];
        }
        out[3] = alpha;
        tile.covered = true;
    }
}

} // namespace sortie::raster
