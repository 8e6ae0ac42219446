#include "GdalDemSource.h"

#include "DemRaster.h"

#include <QCoreApplication>
#include <QDir>

namespace sortie::raster {

using terrain::ElevationSample;

GdalDemSource::~GdalDemSource() = default;

std::unique_ptr<GdalDemSource> GdalDemSource::open(const QString &displayPath, const QStringList &files, QString *error)
{
    std::unique_ptr<GdalDemSource> source(new GdalDemSource);
    source->m_displayPath = displayPath;
    for (const QString &f : files) {
        auto raster = DemRaster::open(f, error);
        if (!raster)
            return nullptr;
        source->m_rasters.push_back(std::move(raster));
    }
    return source;
}

QString GdalDemSource::name() const
{
    return QCoreApplication::translate("GdalDemSource", "DEM (%1)").arg(QDir::toNativeSeparators(m_displayPath));
}

ElevationSample GdalDemSource::sample(const terrain::GeoPoint &point)
{
    if (!point.isValid())
        return ElevationSample::noData();
    if (m_last && m_last->mayCover(point.latitude, point.longitude)) {
        const ElevationSample s = m_last->sample(point.latitude, point.longitude);
        if (s.hasValue())
            return s;
    }
    for (const auto &r : m_rasters) {
        if (r.get() == m_last || !r->mayCover(point.latitude, point.longitude))
            continue;
        const ElevationSample s = r->sample(point.latitude, point.longitude);
        if (s.hasValue()) {
            m_last = r.get();
            return s;
        }
    }
    return ElevationSample::noData();
}

} // namespace sortie::raster
