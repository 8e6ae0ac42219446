#pragma once

#include "ElevationSource.h"

#include <memory>
#include <vector>

namespace sortie::raster {

// A folder holding both SRTM .hgt tiles and other rasters: its parts asked in turn, the first
// value wins (the hand-written .hgt reader first, then GDAL's rasters).
class DemFolderSource : public terrain::ElevationSource
{
    Q_OBJECT

public:
    DemFolderSource(QString folder, std::vector<std::unique_ptr<terrain::ElevationSource>> parts);
    ~DemFolderSource() override;

    QString name() const override;
    terrain::ElevationSample sample(const terrain::GeoPoint &point) override;
    QStringList problems() const override;

private:
    QString m_folder;
    std::vector<std::unique_ptr<terrain::ElevationSource>> m_parts;
};

} // namespace sortie::raster
