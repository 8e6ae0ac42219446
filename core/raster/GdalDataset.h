#pragma once

#include <QString>
#include <QByteArray>

#include <memory>

class GDALDataset;

namespace sortie::raster {

struct GdalDatasetCloser
{
    void operator()(GDALDataset *dataset) const;
};
using GdalDatasetPtr = std::unique_ptr<GDALDataset, GdalDatasetCloser>;

// While one lives, GDAL on this thread looks for a raster's side files (.aux.xml, .ovr, .prj, world
// files) one by one instead of listing its folder: reading a raster's georeferencing listed the whole
// folder (GDAL's GeoTIFF driver ignores a listing given to it), so opening each of a folder's thousand
// tiles read a thousand names. What GDAL finds is the same; only the way it looks changes.
class FolderNotListed
{
public:
    FolderNotListed();
    ~FolderNotListed();
    FolderNotListed(const FolderNotListed &) = delete;
    FolderNotListed &operator=(const FolderNotListed &) = delete;

private:
    QByteArray m_previous;
    bool m_hadPrevious = false;
};

// Opens `path` read-only as a GDAL raster (GDAL's drivers registered on first use). Null, with an
// error naming the file and GDAL's own reason, when GDAL cannot read it or it has no raster band.
// A dataset belongs to one thread at a time: GDAL datasets are not safe to share.
GdalDatasetPtr openRaster(const QString &path, QString *error);

// The message of GDAL's last error on this thread, or `fallback` when it gave none.
QString lastGdalError(const QString &fallback);

} // namespace sortie::raster
