#pragma once

#include "ElevationSource.h"

#include <QStringList>

#include <memory>
#include <vector>

namespace sortie::raster {

class DemRaster;

// Terrain from elevation rasters GDAL reads: one file, or several (a folder's, a list). A point is
// asked of the raster that answered last, then of each whose box holds it, in the order given; the
// first value wins. Synchronous: it answers at once from the files.
class GdalDemSource : public terrain::ElevationSource
{
    Q_OBJECT

public:
    // Every file must open (DemRaster::open); null with the first file's error otherwise.
    static std::unique_ptr<GdalDemSource> open(const QString &displayPath, const QStringList &files, QString *error);
    ~GdalDemSource() override;

    QString name() const override;
    terrain::ElevationSample sample(const terrain::GeoPoint &point) override;
    int rasterCount() const { return int(m_rasters.size()); }
    const DemRaster &raster(int i) const { return *m_rasters[size_t(i)]; }

private:
    GdalDemSource() = default;
    QString m_displayPath;
    std::vector<std::unique_ptr<DemRaster>> m_rasters;
    DemRaster *m_last = nullptr;
};

} // namespace sortie::raster
