#include "CoverageMap.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QLoggingCategory>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal_alg.h>
#include <gdal_priv.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>

Q_LOGGING_CATEGORY(lcCoverage, "sortie.coverage")

namespace sortie::coverage {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMaxCells = 64.0 * 1024 * 1024; // 128 MB of counts: a 1 km² survey at 0.125 m


QString gdalError(const QString &what)
{
    const char *message = CPLGetLastErrorMsg();
    return message && *message ? QStringLiteral("%1: %2").arg(what, QString::fromUtf8(message)) : what;
}

void registerGdal()
{
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
}

struct DatasetCloser
{
    void operator()(GDALDataset *d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

struct TransformCloser
{
    void operator()(OGRCoordinateTransformation *t) const { OGRCoordinateTransformation::DestroyCT(t); }
};
using Transform = std::unique_ptr<OGRCoordinateTransformation, TransformCloser>;

// The UTM zone of a place (EPSG 326zz north, 327zz south).
int utmEpsg(double latitude, double longitude)
{
    const int zone = std::clamp(int(std::floor((longitude + 180.0) / 6.0)) + 1, 1, 60);
    return (latitude >= 0 ? 32600 : 32700) + zone;
}

// A photo's footprint on flat ground, looking straight down: the image's height along its heading,
// its width across (the planner's convention, AreaScan.cpp).
struct Footprint
{
    double east = 0, north = 0;      // centre, m in the raster's CRS
    double alongE = 0, alongN = 0;   // unit vector of the heading, grid frame
    double halfAlong = 0, halfAcross = 0;
    double heading = 0;              // degrees, grid frame
    double corner(int i, bool e, double scale = 1.0) const
    {
        const double sa = (i == 0 || i == 3) ? 1 : -1, sc = (i < 2) ? 1 : -1;
        const double acrossE = alongN, acrossN = -alongE;
        return e ? east + scale * (sa * halfAlong * alongE + sc * halfAcross * acrossE)
                 : north + scale * (sa * halfAlong * alongN + sc * halfAcross * acrossN);
    }
    OGRPolygon polygon(double scale = 1.0) const
    {
        OGRLinearRing ring;
        for (int i = 0; i <= 4; ++i)
            ring.addPoint(corner(i % 4, true, scale), corner(i % 4, false, scale));
        OGRPolygon p;
        p.addRing(&ring);
        return p;
    }
};

Spread spreadOf(std::vector<double> values)
{
    Spread s;
    s.count = int(values.size());
    if (values.empty())
        return s;
    std::sort(values.begin(), values.end());
    auto at = [&](double q) { return values[size_t(std::clamp(std::ceil(q * double(values.size())) - 1, 0.0, double(values.size() - 1)))]; };
    s.p5 = at(0.05);
    s.p50 = at(0.50);
    s.p95 = at(0.95);
    s.min = values.front();
    s.max = values.back();
    return s;
}

double headingDifference(double a, double b)
{
    const double d = std::fmod(std::fabs(a - b), 360.0);
    return d > 180 ? 360 - d : d;
}

// Forward overlap with the next photo of the same leg; side overlap with the nearest photo of a
// parallel leg beside it. Both from the footprints' geometry (flat ground, nadir), in percent.
void neighbourOverlaps(const std::vector<Footprint> &f, std::vector<double> *forward, std::vector<double> *side, std::optional<double> *bearing)
{
    double sin2 = 0, cos2 = 0; // the legs' axis: headings doubled, so 0° and 180° agree
    for (size_t i = 0; i < f.size(); ++i) {
        const Footprint &a = f[i];
        auto offsets = [&](const Footprint &b, double *along, double *across) {
            const double dE = b.east - a.east, dN = b.north - a.north;
            *along = dE * a.alongE + dN * a.alongN;
            *across = dE * a.alongN - dN * a.alongE;
        };
        if (i + 1 < f.size() && headingDifference(a.heading, f[i + 1].heading) < 20) {
            double along = 0, across = 0;
            offsets(f[i + 1], &along, &across);
            if (along > 0 && std::fabs(across) < 0.25 * a.halfAcross * 2) {
                forward->push_back(100.0 * std::max(0.0, 1.0 - along / (2 * a.halfAlong)));
                sin2 += std::sin(2 * a.heading * kDeg);
                cos2 += std::cos(2 * a.heading * kDeg);
            }
        }
        double nearest = std::numeric_limits<double>::infinity();
        for (size_t j = 0; j < f.size(); ++j) {
            const double turn = headingDifference(a.heading, f[j].heading);
            if (j == i || (turn > 20 && turn < 160))
                continue;
            double along = 0, across = 0;
            offsets(f[j], &along, &across);
            if (std::fabs(along) < a.halfAlong && std::fabs(across) > 0.25 * a.halfAcross * 2)
                nearest = std::min(nearest, std::fabs(across));
        }
        if (std::isfinite(nearest))
            side->push_back(100.0 * std::max(0.0, 1.0 - nearest / (2 * a.halfAcross)));
    }
    if (!forward->empty()) {
        const double axis = std::atan2(sin2, cos2) / 2 / kDeg;
        *bearing = axis < 0 ? axis + 180 : axis;
    }
}

QJsonValue spreadJson(const std::optional<Spread> &s, int decimals)
{
    if (!s || s->count == 0)
        return QJsonValue::Null; // nothing measured is no figure, never 0
    const double k = std::pow(10.0, decimals);
    auto r = [&](double v) { return std::round(v * k) / k; };
    return QJsonObject{{QStringLiteral("p5"), r(s->p5)}, {QStringLiteral("p50"), r(s->p50)}, {QStringLiteral("p95"), r(s->p95)},
                       {QStringLiteral("min"), r(s->min)}, {QStringLiteral("max"), r(s->max)}, {QStringLiteral("count"), s->count}};
}

Dataset memoryRaster(const CoverageRaster &r, GDALDataType type)
{
    GDALDriver *mem = GetGDALDriverManager()->GetDriverByName("MEM");
    Dataset d(mem ? mem->Create("", r.width, r.height, 1, type, nullptr) : nullptr);
    if (!d)
        return d;
    double transform[6] = {r.originEast, r.cellMeters, 0, r.originNorth, 0, -r.cellMeters};
    d->SetGeoTransform(transform);
    OGRSpatialReference crs;
    if (crs.importFromEPSG(r.epsg) == OGRERR_NONE)
        d->SetSpatialRef(&crs);
    return d;
}

bool burn(GDALDataset &d, std::vector<OGRGeometryH> &geometries, std::vector<double> &values, bool add)
{
    char *options[] = {const_cast<char *>(add ? "MERGE_ALG=ADD" : "MERGE_ALG=REPLACE"), nullptr};
    int band = 1;
    return GDALRasterizeGeometries(GDALDataset::ToHandle(&d), 1, &band, int(geometries.size()), geometries.data(), nullptr, nullptr,
                                   values.data(), options, nullptr, nullptr) == CE_None;
}

} // namespace

std::optional<CoverageReport> computeCoverage(const std::vector<Shot> &shots, const CoverageOptions &options,
                                              CoverageRaster *rasterOut, QString *error)
{
    auto fail = [&](const QString &message) -> std::optional<CoverageReport> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const mission::Camera &camera = options.camera;
    if (!camera.isValid())
        return fail(QCoreApplication::translate("Coverage", "the camera %1 has no sensor size, focal length or resolution").arg(camera.name));
    if (options.minImages < 1 || options.cellMeters < 0 || !std::isfinite(options.cellMeters))
        return fail(QCoreApplication::translate("Coverage", "the minimum number of images and the cell must be positive"));
    registerGdal();

    CoverageReport report;
    report.photos = int(shots.size());
    report.minImages = options.minImages;
    std::vector<const Shot *> usable;
    for (const Shot &s : shots) {
        if (!std::isfinite(s.latitude) || !std::isfinite(s.longitude) || std::fabs(s.latitude) > 90 || std::fabs(s.longitude) > 180)
            report.unplaced.push_back({s.name, QCoreApplication::translate("Coverage", "its position is not a place")});
        else if (!std::isfinite(s.heightAboveGround))
            report.unplaced.push_back({s.name, QCoreApplication::translate("Coverage", "its height above the ground is not known")});
        else if (s.heightAboveGround < 1)
            report.unplaced.push_back({s.name, QCoreApplication::translate("Coverage", "taken %1 m above the ground: on the ground, not surveying").arg(s.heightAboveGround, 0, 'f', 1)});
        else if (!std::isfinite(s.headingDegrees))
            report.unplaced.push_back({s.name, QCoreApplication::translate("Coverage", "its heading is not known")});
        else
            usable.push_back(&s);
    }
    if (usable.empty())
        return fail(QCoreApplication::translate("Coverage", "no photo has a position, a height above the ground and a heading"));

    // The raster's CRS: the UTM zone of the photos' middle, so cells are square metres.
    double latSum = 0, lonSum = 0;
    for (const Shot *s : usable) {
        latSum += s->latitude;
        lonSum += s->longitude;
    }
    const int epsg = utmEpsg(latSum / double(usable.size()), lonSum / double(usable.size()));
    OGRSpatialReference wgs84, utm;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (utm.importFromEPSG(epsg) != OGRERR_NONE)
        return fail(gdalError(QCoreApplication::translate("Coverage", "PROJ does not know EPSG:%1 (is proj-data installed?)").arg(epsg)));
    utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    const Transform toUtm(OGRCreateCoordinateTransformation(&wgs84, &utm));
    const Transform toWgs84(OGRCreateCoordinateTransformation(&utm, &wgs84));
    if (!toUtm || !toWgs84)
        return fail(gdalError(QCoreApplication::translate("Coverage", "no transformation between WGS-84 and EPSG:%1").arg(epsg)));

    std::vector<Footprint> footprints;
    footprints.reserve(usable.size());
    double widthSum = 0;
    std::vector<double> gsd, heights;
    const double gsdPerMetre = std::max(camera.sensorWidthMm / (camera.focalLengthMm * camera.imageWidthPx),
                                        camera.sensorHeightMm / (camera.focalLengthMm * camera.imageHeightPx));
    for (const Shot *s : usable) {
        // The heading in the grid: true north turned by the meridian's convergence at the photo.
        double x[2] = {s->longitude, s->longitude}, y[2] = {s->latitude, std::min(89.999, s->latitude + 0.001)};
        if (!toUtm->Transform(2, x, y)) {
            report.unplaced.push_back({s->name, QCoreApplication::translate("Coverage", "it cannot be placed in EPSG:%1").arg(epsg)});
            continue;
        }
        const double convergence = std::atan2(x[1] - x[0], y[1] - y[0]) / kDeg;
        Footprint f;
        f.east = x[0];
        f.north = y[0];
        f.heading = s->headingDegrees + convergence;
        f.alongE = std::sin(f.heading * kDeg);
        f.alongN = std::cos(f.heading * kDeg);
        f.halfAlong = 0.5 * s->heightAboveGround * camera.sensorHeightMm / camera.focalLengthMm;
        f.halfAcross = 0.5 * s->heightAboveGround * camera.sensorWidthMm / camera.focalLengthMm;
        widthSum += 2 * f.halfAcross;
        gsd.push_back(s->heightAboveGround * gsdPerMetre * 100.0);
        heights.push_back(s->heightAboveGround);
        footprints.push_back(f);
    }
    if (footprints.empty())
        return fail(QCoreApplication::translate("Coverage", "no photo could be placed in EPSG:%1").arg(epsg));
    report.placed = int(footprints.size());
    report.crs = QStringLiteral("EPSG:%1").arg(epsg);
    report.gsdCm = spreadOf(gsd);
    report.heightAboveGround = spreadOf(heights);

    CoverageRaster raster;
    raster.epsg = epsg;
    raster.cellMeters = options.cellMeters > 0 ? options.cellMeters : std::max(0.1, widthSum / double(footprints.size()) / 200.0);
    double minE = std::numeric_limits<double>::infinity(), maxE = -minE, minN = minE, maxN = -minE;
    for (const Footprint &f : footprints)
        for (int i = 0; i < 4; ++i) {
            minE = std::min(minE, f.corner(i, true));
            maxE = std::max(maxE, f.corner(i, true));
            minN = std::min(minN, f.corner(i, false));
            maxN = std::max(maxN, f.corner(i, false));
        }
    const double cells = std::ceil((maxE - minE) / raster.cellMeters + 2) * std::ceil((maxN - minN) / raster.cellMeters + 2);
    if (cells > kMaxCells)
        return fail(QCoreApplication::translate("Coverage", "the photos span %1 × %2 m: %3 m cells would make %4 million, more than the %5 million a raster may hold; choose a larger cell")
                        .arg(std::lround(maxE - minE)).arg(std::lround(maxN - minN)).arg(raster.cellMeters).arg(std::lround(cells / 1e6)).arg(std::lround(kMaxCells / 1e6)));
    raster.originEast = std::floor(minE / raster.cellMeters - 1) * raster.cellMeters;
    raster.originNorth = std::ceil(maxN / raster.cellMeters + 1) * raster.cellMeters;
    raster.width = int(std::ceil((maxE - raster.originEast) / raster.cellMeters)) + 1;
    raster.height = int(std::ceil((raster.originNorth - minN) / raster.cellMeters)) + 1;
    report.cellMeters = raster.cellMeters;

    // Images per cell: every footprint burnt in with GDAL's rasteriser, adding 1 (a cell counts when
    // its centre is inside).
    const Dataset counts = memoryRaster(raster, GDT_UInt16);
    const Dataset area = memoryRaster(raster, GDT_Byte);
    if (!counts || !area)
        return fail(gdalError(QCoreApplication::translate("Coverage", "GDAL cannot make a %1 × %2 raster in memory").arg(raster.width).arg(raster.height)));
    std::vector<OGRPolygon> polygons;
    polygons.reserve(footprints.size());
    for (const Footprint &f : footprints)
        polygons.push_back(f.polygon());
    std::vector<OGRGeometryH> handles;
    for (OGRPolygon &p : polygons)
        handles.push_back(OGRGeometry::ToHandle(&p));
    std::vector<double> ones(handles.size(), 1.0);
    if (!burn(*counts, handles, ones, true))
        return fail(gdalError(QCoreApplication::translate("Coverage", "GDAL cannot rasterise the footprints")));

    // The ground judged: the convex hull of the photos' centres (a survey's outer legs and leg ends
    // are seen by fewer images than its middle, and its margins beyond them by fewer still). Photos
    // in one line (a corridor) judge a strip half a footprint wide.
    OGRMultiPoint centres;
    for (const Footprint &f : footprints) {
        OGRPoint p(f.east, f.north);
        centres.addGeometry(&p);
    }
    std::unique_ptr<OGRGeometry> hull(centres.ConvexHull());
    const double meanWidth = widthSum / double(footprints.size());
    const bool thin = !hull || hull->getGeometryType() != wkbPolygon || hull->toPolygon()->get_Area() < 0.01 * meanWidth * meanWidth;
    if (hull && thin)
        hull.reset(hull->Buffer(0.25 * meanWidth));
    if (!hull || hull->getGeometryType() != wkbPolygon)
        return fail(QCoreApplication::translate("Coverage", "the photos cover no area"));
    std::vector<OGRGeometryH> hullHandle{OGRGeometry::ToHandle(hull.get())};
    std::vector<double> one{1.0};
    if (!burn(*area, hullHandle, one, false))
        return fail(gdalError(QCoreApplication::translate("Coverage", "GDAL cannot rasterise the surveyed area")));

    raster.images.resize(size_t(raster.width) * size_t(raster.height));
    std::vector<uint8_t> inside(raster.images.size());
    if (counts->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, raster.width, raster.height, raster.images.data(), raster.width, raster.height, GDT_UInt16, 0, 0) != CE_None
        || area->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, raster.width, raster.height, inside.data(), raster.width, raster.height, GDT_Byte, 0, 0) != CE_None)
        return fail(gdalError(QCoreApplication::translate("Coverage", "GDAL cannot read its raster back")));

    std::vector<double> perPoint;
    perPoint.reserve(inside.size());
    size_t enough = 0;
    std::vector<uint8_t> holeMask(inside.size(), 0);
    for (size_t i = 0; i < inside.size(); ++i) {
        if (!inside[i])
            continue;
        perPoint.push_back(raster.images[i]);
        if (raster.images[i] >= options.minImages)
            ++enough;
        else
            holeMask[i] = 1;
    }
    const double cellArea = raster.cellMeters * raster.cellMeters;
    report.areaSquareMeters = double(perPoint.size()) * cellArea;
    report.coveredFraction = perPoint.empty() ? 0 : double(enough) / double(perPoint.size());
    report.imagesPerPoint = spreadOf(std::move(perPoint));

    std::vector<double> forward, side;
    std::optional<double> gridBearing;
    neighbourOverlaps(footprints, &forward, &side, &gridBearing);
    if (gridBearing) {
        // Back from the grid to true north, by the convergence at the survey's middle.
        double x[2] = {lonSum / double(usable.size()), lonSum / double(usable.size())};
        double y[2] = {latSum / double(usable.size()), latSum / double(usable.size()) + 0.001};
        const double convergence = toUtm->Transform(2, x, y) ? std::atan2(x[1] - x[0], y[1] - y[0]) / kDeg : 0.0;
        const double bearing = std::fmod(*gridBearing - convergence + 360.0, 180.0);
        report.legBearing = bearing;
    }
    report.forwardOverlap = spreadOf(std::move(forward));
    report.sideOverlap = spreadOf(std::move(side));

    // The holes: the cells of the area seen too few times, traced into polygons by GDAL.
    const Dataset holeRaster = memoryRaster(raster, GDT_Byte);
    GDALDriver *memoryVectors = GetGDALDriverManager()->GetDriverByName("Memory");
    const Dataset vectors(memoryVectors ? memoryVectors->Create("", 0, 0, 0, GDT_Unknown, nullptr) : nullptr);
    OGRLayer *layer = vectors ? vectors->CreateLayer("holes", &utm, wkbPolygon, nullptr) : nullptr;
    if (!holeRaster || !layer)
        return fail(gdalError(QCoreApplication::translate("Coverage", "GDAL cannot make the holes' layer")));
    OGRFieldDefn value("value", OFTInteger);
    layer->CreateField(&value);
    GDALRasterBand *holeBand = holeRaster->GetRasterBand(1);
    if (holeBand->RasterIO(GF_Write, 0, 0, raster.width, raster.height, holeMask.data(), raster.width, raster.height, GDT_Byte, 0, 0) != CE_None
        || GDALPolygonize(GDALRasterBand::ToHandle(holeBand), GDALRasterBand::ToHandle(holeBand), OGRLayer::ToHandle(layer), 0, nullptr, nullptr, nullptr) != CE_None)
        return fail(gdalError(QCoreApplication::translate("Coverage", "GDAL cannot trace the holes")));
    layer->ResetReading();
    while (OGRFeature *feature = layer->GetNextFeature()) {
        std::unique_ptr<OGRFeature> owned(feature);
        const OGRPolygon *polygon = dynamic_cast<const OGRPolygon *>(feature->GetGeometryRef());
        if (!polygon || polygon->get_Area() < options.minHoleArea)
            continue;
        Hole hole;
        hole.areaSquareMeters = polygon->get_Area();
        OGRPoint centre;
        polygon->Centroid(&centre);
        double cx = centre.getX(), cy = centre.getY();
        toWgs84->Transform(1, &cx, &cy);
        hole.centreLongitude = cx;
        hole.centreLatitude = cy;
        // The ring follows the cells' edges: simplified to within a cell, it says the same in fewer points.
        std::unique_ptr<OGRGeometry> simple(polygon->SimplifyPreserveTopology(raster.cellMeters));
        const OGRPolygon *outline = simple && simple->getGeometryType() == wkbPolygon ? simple->toPolygon() : polygon;
        const OGRLinearRing *ring = outline->getExteriorRing();
        for (int i = 0; ring && i < ring->getNumPoints(); ++i) {
            double px = ring->getX(i), py = ring->getY(i);
            toWgs84->Transform(1, &px, &py);
            hole.ring.emplace_back(px, py);
        }
        std::unique_ptr<OGRGeometry> grown(polygon->Buffer(0.25 * meanWidth));
        std::unique_ptr<OGRGeometry> scan(grown ? grown->ConvexHull() : nullptr);
        if (scan && scan->getGeometryType() == wkbPolygon) {
            const OGRLinearRing *outer = scan->toPolygon()->getExteriorRing();
            for (int i = 0; outer && i < outer->getNumPoints(); ++i) {
                double px = outer->getX(i), py = outer->getY(i);
                toWgs84->Transform(1, &px, &py);
                hole.scanRing.emplace_back(px, py);
            }
        }
        report.holes.push_back(std::move(hole));
    }
    std::sort(report.holes.begin(), report.holes.end(), [](const Hole &a, const Hole &b) { return a.areaSquareMeters > b.areaSquareMeters; });
    qCInfo(lcCoverage).noquote() << report.placed << "of" << report.photos << "photos placed on a" << raster.width << "×" << raster.height
                                 << "raster of" << raster.cellMeters << "m in" << report.crs << ":" << report.holes.size() << "holes";
    if (rasterOut)
        *rasterOut = std::move(raster);
    return report;
}

bool writeCoverageGeoTiff(const CoverageRaster &raster, const QString &path, QString *error)
{
    auto fail = [&](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    registerGdal();
    if (raster.width <= 0 || raster.height <= 0 || raster.images.size() != size_t(raster.width) * size_t(raster.height))
        return fail(QCoreApplication::translate("Coverage", "no raster to write"));
    GDALDriver *gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
    if (!gtiff)
        return fail(QCoreApplication::translate("Coverage", "GDAL has no GeoTIFF driver"));
    const QFileInfo target(path);
    const QString partial = target.dir().filePath(QStringLiteral(".%1.sortie-coverage").arg(target.fileName()));
    char *options[] = {const_cast<char *>("COMPRESS=DEFLATE"), const_cast<char *>("TILED=YES"), nullptr};
    {
        Dataset out(gtiff->Create(QFile::encodeName(partial).constData(), raster.width, raster.height, 1, GDT_UInt16, options));
        if (!out)
            return fail(gdalError(QCoreApplication::translate("Coverage", "%1 cannot be written").arg(path)));
        double transform[6] = {raster.originEast, raster.cellMeters, 0, raster.originNorth, 0, -raster.cellMeters};
        out->SetGeoTransform(transform);
        OGRSpatialReference crs;
        if (crs.importFromEPSG(raster.epsg) == OGRERR_NONE)
            out->SetSpatialRef(&crs);
        GDALRasterBand *band = out->GetRasterBand(1);
        band->SetDescription("images per cell"); // i18n: not text (the file's band name, read by GIS tools in any language)
        if (band->RasterIO(GF_Write, 0, 0, raster.width, raster.height, const_cast<uint16_t *>(raster.images.data()), raster.width,
                           raster.height, GDT_UInt16, 0, 0) != CE_None) {
            out.reset();
            QFile::remove(partial);
            return fail(gdalError(QCoreApplication::translate("Coverage", "%1 cannot be written").arg(path)));
        }
    } // closed: the file is complete
    QFile::remove(path);
    if (!QFile::rename(partial, path)) {
        QFile::remove(partial);
        return fail(QCoreApplication::translate("Coverage", "%1 cannot be put in place").arg(path));
    }
    return true;
}

QJsonObject CoverageReport::toJson() const
{
    QJsonArray holeList;
    for (const Hole &h : holes) {
        QJsonArray ring;
        for (const auto &[lon, lat] : h.ring)
            ring.append(QJsonArray{std::round(lon * 1e7) / 1e7, std::round(lat * 1e7) / 1e7});
        holeList.append(QJsonObject{{QStringLiteral("area"), std::round(h.areaSquareMeters * 10) / 10},
                                    {QStringLiteral("centre"), QJsonArray{std::round(h.centreLongitude * 1e7) / 1e7, std::round(h.centreLatitude * 1e7) / 1e7}},
                                    {QStringLiteral("polygon"), ring}});
    }
    QJsonArray unplacedList;
    for (const Unplaced &u : unplaced)
        unplacedList.append(QJsonObject{{QStringLiteral("file"), u.file}, {QStringLiteral("reason"), u.reason}});
    return QJsonObject{
        {QStringLiteral("photos"), photos},
        {QStringLiteral("placed"), placed},
        {QStringLiteral("unplaced"), unplacedList},
        {QStringLiteral("crs"), crs},
        {QStringLiteral("cell"), std::round(cellMeters * 1000) / 1000},
        {QStringLiteral("minImages"), minImages},
        {QStringLiteral("area"), std::round(areaSquareMeters)},
        {QStringLiteral("covered"), std::round(coveredFraction * 10000) / 10000},
        {QStringLiteral("imagesPerPoint"), spreadJson(imagesPerPoint, 0)},
        {QStringLiteral("forwardOverlap"), spreadJson(forwardOverlap, 1)},
        {QStringLiteral("sideOverlap"), spreadJson(sideOverlap, 1)},
        {QStringLiteral("gsdCm"), spreadJson(gsdCm, 2)},
        {QStringLiteral("heightAboveGround"), spreadJson(heightAboveGround, 1)},
        {QStringLiteral("legBearing"), legBearing ? QJsonValue(std::round(*legBearing * 10) / 10) : QJsonValue(QJsonValue::Null)},
        {QStringLiteral("holes"), holeList},
    };
}

} // namespace sortie::coverage
