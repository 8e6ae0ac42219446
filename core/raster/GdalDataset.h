#pragma once

#include <QString>
#include <QStringList>

#include <memory>

class GDALDataset;

namespace sortie::raster {

struct GdalDatasetCloser
{
    void operator()(GDALDataset *dataset) const;
};
using GdalDatasetPtr = std::unique_ptr<GDALDataset, GdalDatasetCloser>;

// A folder's file names, as GDAL takes them when opening one of its files: given, GDAL does not list
// the folder again for each file it opens (for .aux.xml, .ovr, .hdr side files), which made opening
// each of a thousand tiles read a thousand names.
class FolderListing
{
public:
    FolderListing(QString folder, const QStringList &names);
    ~FolderListing();
    FolderListing(const FolderListing &) = delete;
    FolderListing &operator=(const FolderListing &) = delete;
    const QString &folder() const { return m_folder; }
    char **names() const { return m_names; }

private:
    QString m_folder;
    char **m_names = nullptr;
};

// Opens `path` read-only as a GDAL raster (GDAL's drivers registered on first use). Null, with an
// error naming the file and GDAL's own reason, when GDAL cannot read it or it has no raster band.
// A dataset belongs to one thread at a time: GDAL datasets are not safe to share.
// `siblings`, when given, is the listing of the folder `path` is in.
GdalDatasetPtr openRaster(const QString &path, QString *error, const FolderListing *siblings = nullptr);

// The message of GDAL's last error on this thread, or `fallback` when it gave none.
QString lastGdalError(const QString &fallback);

} // namespace sortie::raster
