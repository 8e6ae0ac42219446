#pragma once

#include <QString>

#include <memory>

class GDALDataset;

namespace sortie::raster {

struct GdalDatasetCloser
{
    void operator()(GDALDataset *dataset) const;
};
using GdalDatasetPtr = std::unique_ptr<GDALDataset, GdalDatasetCloser>;

// Opens `path` read-only as a GDAL raster (GDAL's drivers registered on first use). Null, with an
// error naming the file and GDAL's own reason, when GDAL cannot read it or it has no raster band.
// A dataset belongs to one thread at a time: GDAL datasets are not safe to share.
GdalDatasetPtr openRaster(const QString &path, QString *error);

// The message of GDAL's last error on this thread, or `fallback` when it gave none.
QString lastGdalError(const QString &fallback);

} // namespace sortie::raster
