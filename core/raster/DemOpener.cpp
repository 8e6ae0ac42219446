#include "DemOpener.h"

#include "DemFolderSource.h"
#include "GdalDemSource.h"
#include "HgtTile.h"
#include "IndexedDemSource.h"
#include "HgtTileSource.h"
#include "RasterLog.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace sortie::raster {

namespace {

std::unique_ptr<terrain::ElevationSource> hgtSource(const QString &path, QString *error)
{
    auto tiles = std::make_unique<terrain::HgtTileSource>(path);
    if (!tiles->isUsable()) {
        if (error)
            *error = tiles->error();
        return nullptr;
    }
    return tiles;
}

std::unique_ptr<terrain::ElevationSource> openFolder(const QString &path, QString *error)
{
    const QDir dir(path);
    QStringList rasters;
    bool hasHgt = false;
    for (const QFileInfo &f : dir.entryInfoList(QDir::Files | QDir::Readable, QDir::Name)) {
        const QString suffix = f.suffix().toLower();
        if (suffix == QLatin1String("hgt"))
            hasHgt = true;
        else if (demFileSuffixes().contains(suffix))
            rasters << f.filePath();
    }
    if (rasters.isEmpty())
        return hgtSource(path, error);  // an SRTM folder, as before (an empty one has no tiles)
    // Headers only now: a raster is opened when a point falls in its box (thousands of tiles open at once).
    auto gdal = IndexedDemSource::open(path, rasters, error);
    if (!gdal)
        return nullptr;
    qCInfo(lcRaster).noquote() << gdal->indexedCount() << "of" << rasters.size() << "raster(s) indexed through GDAL in" << path;
    if (!hasHgt)
        return gdal;
    std::vector<std::unique_ptr<terrain::ElevationSource>> parts;
    auto tiles = hgtSource(path, error);
    if (!tiles)
        return nullptr;
    parts.push_back(std::move(tiles));
    parts.push_back(std::move(gdal));
    return std::make_unique<DemFolderSource>(path, std::move(parts));
}

} // namespace

QStringList demFileSuffixes()
{
    return {QStringLiteral("tif"), QStringLiteral("tiff"), QStringLiteral("vrt"), QStringLiteral("dt0"), QStringLiteral("dt1"),
            QStringLiteral("dt2"), QStringLiteral("asc"), QStringLiteral("img"), QStringLiteral("bil"), QStringLiteral("flt"),
            QStringLiteral("dem")};
}

std::unique_ptr<terrain::ElevationSource> openDem(const QString &path, QString *error)
{
    const QFileInfo info(path);
    if (info.isDir())
        return openFolder(path, error);
    if (!info.exists()) {
        if (error)
            *error = QCoreApplication::translate("DemOpener", "%1: no such file or folder").arg(path);
        return nullptr;
    }
    if (info.suffix().compare(QLatin1String("hgt"), Qt::CaseInsensitive) == 0 && terrain::parseHgtName(info.fileName()))
        return hgtSource(path, error);
    return GdalDemSource::open(path, {path}, error);
}

} // namespace sortie::raster
