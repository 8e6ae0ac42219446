#include "DemFolderSource.h"

#include <QCoreApplication>
#include <QDir>

namespace sortie::raster {

DemFolderSource::DemFolderSource(QString folder, std::vector<std::unique_ptr<terrain::ElevationSource>> parts)
    : m_folder(std::move(folder)), m_parts(std::move(parts))
{
}

DemFolderSource::~DemFolderSource() = default;

QString DemFolderSource::name() const
{
    return QCoreApplication::translate("DemFolderSource", "DEM folder (%1)").arg(QDir::toNativeSeparators(m_folder));
}

QStringList DemFolderSource::problems() const
{
    QStringList all;
    for (const auto &part : m_parts)
        all << part->problems();
    return all;
}

terrain::ElevationSample DemFolderSource::sample(const terrain::GeoPoint &point)
{
    for (const auto &part : m_parts) {
        const terrain::ElevationSample s = part->sample(point);
        if (s.hasValue())
            return s;
    }
    return terrain::ElevationSample::noData();
}

} // namespace sortie::raster
