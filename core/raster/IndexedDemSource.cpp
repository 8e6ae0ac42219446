#include "IndexedDemSource.h"

#include "DemRaster.h"
#include "GdalDataset.h"
#include "RasterLog.h"

#include <QCoreApplication>
#include <QDir>
#ifndef BOOST_GEOMETRY_NO_ROBUSTNESS
#define BOOST_GEOMETRY_NO_ROBUSTNESS // as core/airspace (PlaneZone.h): one Boost.Geometry configuration in the program
#endif
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/iterator/function_output_iterator.hpp>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <map>
#include <string>

namespace sortie::raster {

using terrain::ElevationSample;
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {

using TransformPtr = std::unique_ptr<OGRCoordinateTransformation, void (*)(OGRCoordinateTransformation *)>;
void destroyTransform(OGRCoordinateTransformation *t)
{
    OGRCoordinateTransformation::DestroyCT(t);
}

// Transformations into WGS-84, one per CRS met: creating one costs far more than reading a header.
class ToWgs84
{
public:
    ToWgs84()
    {
        m_wgs84.importFromEPSG(4326);
        m_wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    }
    // Null `*out` for WGS-84 degrees; false when PROJ knows no way.
    bool from(const OGRSpatialReference &srs, OGRCoordinateTransformation **out)
    {
        char *wkt = nullptr;
        srs.exportToWkt(&wkt);
        const std::string key = wkt ? wkt : "";
        CPLFree(wkt);
        auto found = m_transforms.find(key);
        if (found == m_transforms.end()) {
            OGRSpatialReference source(srs);
            source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
            TransformPtr t{nullptr, destroyTransform};
            bool usable = true;
            if (!(source.IsGeographic() && source.IsSameGeogCS(&m_wgs84))) {
                t.reset(OGRCreateCoordinateTransformation(&source, &m_wgs84));
                usable = bool(t);
            }
            found = m_transforms.emplace(key, std::make_pair(usable, std::move(t))).first;
        }
        *out = found->second.second.get();
        return found->second.first;
    }

private:
    OGRSpatialReference m_wgs84;
    std::map<std::string, std::pair<bool, TransformPtr>> m_transforms;
};

// The file's WGS-84 box from its header; the dataset is closed again at once.
std::optional<GeoBox> readFootprint(const QString &path, ToWgs84 &toWgs84, QString *error)
{
    auto fail = [&](const QString &why) {
        *error = QStringLiteral("%1: %2").arg(path, why);
        return std::nullopt;
    };
    const GdalDatasetPtr dataset = openRaster(path, error);
    if (!dataset)
        return std::nullopt;
    double toWorld[6];
    if (dataset->GetGeoTransform(toWorld) != CE_None)
        return fail(QCoreApplication::translate("DemRaster", "the raster is not georeferenced (no geotransform)"));
    const int width = dataset->GetRasterXSize(), height = dataset->GetRasterYSize();
    if (const QString problem = geoTransformProblem(toWorld, width, height); !problem.isEmpty())
        return fail(problem);
    const OGRSpatialReference *srs = dataset->GetSpatialRef();
    if (!srs || srs->IsEmpty())
        return fail(QCoreApplication::translate("DemRaster", "the raster states no coordinate reference system"));
    OGRCoordinateTransformation *transform = nullptr;
    CPLErrorReset();
    if (!toWgs84.from(*srs, &transform))
        return fail(QCoreApplication::translate("DemRaster", "no transformation from WGS-84 into the raster's CRS: %1")
                        .arg(lastGdalError(QCoreApplication::translate("DemRaster", "PROJ gave no reason"))));
    const std::optional<GeoBox> box = footprintInWgs84(toWorld, width, height, transform);
    if (!box)
        return fail(QCoreApplication::translate("DemRaster", "the raster's extent cannot be expressed in WGS-84 degrees"));
    return box;
}

} // namespace

// Keeps Boost.Geometry out of the header. Boxes are (longitude, latitude), widened by GeoBox's slack.
class IndexedDemSource::Tree
{
public:
    using Point = bg::model::point<double, 2, bg::cs::cartesian>;
    using Box = bg::model::box<Point>;
    using Value = std::pair<Box, int>;

    explicit Tree(const std::vector<Value> &values) : m_tree(values.begin(), values.end()) {}  // packed (bulk) load

    void query(double latitude, double longitude, std::vector<int> &out) const
    {
        out.clear();
        m_tree.query(bgi::intersects(Point(longitude, latitude)), boost::make_function_output_iterator([&](const Value &v) {
                         out.push_back(v.second);
                     }));
        std::sort(out.begin(), out.end());  // the order the files were given
    }

private:
    bgi::rtree<Value, bgi::rstar<16>> m_tree;
};

IndexedDemSource::IndexedDemSource() = default;
IndexedDemSource::~IndexedDemSource() = default;

std::unique_ptr<IndexedDemSource> IndexedDemSource::open(const QString &displayPath, const QStringList &files, QString *error, int maxOpen)
{
    std::unique_ptr<IndexedDemSource> source(new IndexedDemSource);
    source->m_displayPath = displayPath;
    source->m_maxOpen = std::max(1, maxOpen);
    const FolderNotListed notListed;
    ToWgs84 toWgs84;
    QString firstError;
    for (const QString &path : files) {
        QString why;
        if (const std::optional<GeoBox> box = readFootprint(path, toWgs84, &why)) {
            source->m_entries.push_back({path, *box});
        } else {
            source->addProblem(why);
            if (firstError.isEmpty())
                firstError = why;
        }
    }
    if (source->m_entries.empty()) {
        if (error)
            *error = firstError.isEmpty() ? QCoreApplication::translate("IndexedDemSource", "%1: no rasters").arg(displayPath) : firstError;
        return nullptr;
    }
    source->buildTree();
    return source;
}

void IndexedDemSource::buildTree()
{
    std::vector<Tree::Value> values;
    values.reserve(m_entries.size());
    constexpr double slack = 1e-9;
    for (size_t i = 0; i < m_entries.size(); ++i) {
        const GeoBox &b = m_entries[i].box;
        values.emplace_back(Tree::Box({b.west - slack, b.south - slack}, {b.east + slack, b.north + slack}), int(i));
    }
    m_tree = std::make_unique<Tree>(values);
}

void IndexedDemSource::addProblem(const QString &problem)
{
    qCWarning(lcRaster).noquote() << problem << "- left out of" << m_displayPath;
    m_problems << problem;
}

QString IndexedDemSource::name() const
{
    return QCoreApplication::translate("GdalDemSource", "DEM (%1)").arg(QDir::toNativeSeparators(m_displayPath));
}

DemRaster *IndexedDemSource::raster(int entry)
{
    if (auto found = m_open.find(entry); found != m_open.end()) {
        m_recent.splice(m_recent.begin(), m_recent, found->second.place);
        return found->second.raster.get();
    }
    Entry &e = m_entries[size_t(entry)];
    if (e.broken)
        return nullptr;
    QString why;
    const FolderNotListed notListed;
    std::unique_ptr<DemRaster> opened = DemRaster::open(e.path, &why, DemRaster::kDefaultMaxChunks, !e.openedBefore);
    if (!opened) {
        e.broken = true;  // its header read, its data not (ellipsoidal without the geoid, changed on disk)
        addProblem(why);
        return nullptr;
    }
    ++m_opens;
    e.openedBefore = true;
    if (int(m_open.size()) >= m_maxOpen) {
        m_open.erase(m_recent.back());  // closes its dataset
        m_recent.pop_back();
    }
    m_recent.push_front(entry);
    OpenRaster &stored = m_open[entry];
    stored.raster = std::move(opened);
    stored.place = m_recent.begin();
    return stored.raster.get();
}

ElevationSample IndexedDemSource::sampleEntry(int entry, double latitude, double longitude)
{
    DemRaster *r = raster(entry);
    return r ? r->sample(latitude, longitude) : ElevationSample::noData();
}

ElevationSample IndexedDemSource::sample(const terrain::GeoPoint &point)
{
    if (!point.isValid())
        return ElevationSample::noData();
    const double lat = point.latitude, lon = point.longitude;
    if (m_last >= 0 && m_entries[size_t(m_last)].box.contains(lat, lon)) {
        const ElevationSample s = sampleEntry(m_last, lat, lon);
        if (s.hasValue())
            return s;
    }
    m_tree->query(lat, lon, m_candidates);
    for (int entry : m_candidates) {
        if (entry == m_last)
            continue;
        const ElevationSample s = sampleEntry(entry, lat, lon);
        if (s.hasValue()) {
            m_last = entry;
            return s;
        }
    }
    return ElevationSample::noData();
}

} // namespace sortie::raster
