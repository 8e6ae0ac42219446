#include "GdalDataset.h"

#include <QCoreApplication>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal_priv.h>

#include <cpl_vsi.h>

#include <mutex>

namespace sortie::raster {

void GdalDatasetCloser::operator()(GDALDataset *dataset) const
{
    GDALClose(GDALDataset::ToHandle(dataset));
}

QString lastGdalError(const QString &fallback)
{
    const char *message = CPLGetLastErrorMsg();
    return message && *message ? QString::fromUtf8(message) : fallback;
}

namespace {
const char kNoListing[] = "GDAL_DISABLE_READDIR_ON_OPEN";
}

FolderNotListed::FolderNotListed()
{
    if (const char *previous = CPLGetThreadLocalConfigOption(kNoListing, nullptr))
        m_previous = previous, m_hadPrevious = true;
    CPLSetThreadLocalConfigOption(kNoListing, "TRUE");
}

FolderNotListed::~FolderNotListed()
{
    CPLSetThreadLocalConfigOption(kNoListing, m_hadPrevious ? m_previous.constData() : nullptr);
}

GdalDatasetPtr openRaster(const QString &path, QString *error)
{
    static std::once_flag registered;
    std::call_once(registered, [] { GDALAllRegister(); });
    auto fail = [&](const QString &why) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, why);
        return GdalDatasetPtr();
    };
    VSIStatBufL stat;  // through GDAL's file system: /vsimem/, /vsizip/... paths exist too
    if (VSIStatExL(path.toUtf8().constData(), &stat, VSI_STAT_EXISTS_FLAG) != 0)
        return fail(QCoreApplication::translate("GdalDataset", "no such file"));
    // GDAL reports its reasons through the error handler; keep them for the message instead of stderr.
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    GdalDatasetPtr dataset(GDALDataset::Open(path.toUtf8().constData(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    CPLPopErrorHandler();
    if (!dataset)
        return fail(lastGdalError(QCoreApplication::translate("GdalDataset", "GDAL knows no raster format for this file")));
    if (dataset->GetRasterCount() < 1)
        return fail(QCoreApplication::translate("GdalDataset", "the file has no raster band"));
    return dataset;
}

} // namespace sortie::raster
