#include "GdalDataset.h"

#include <QCoreApplication>
#include <cpl_error.h>
#include <gdal_priv.h>

#include <QFileInfo>

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

FolderListing::FolderListing(QString folder, const QStringList &names) : m_folder(std::move(folder))
{
    for (const QString &name : names)
        m_names = CSLAddString(m_names, name.toUtf8().constData());
    if (!m_names)  // an empty folder is still a listing (null would make GDAL list it)
        m_names = static_cast<char **>(CPLCalloc(1, sizeof(char *)));
}

FolderListing::~FolderListing()
{
    CSLDestroy(m_names);
}

GdalDatasetPtr openRaster(const QString &path, QString *error, const FolderListing *siblings)
{
    static std::once_flag registered;
    std::call_once(registered, [] { GDALAllRegister(); });
    auto fail = [&](const QString &why) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, why);
        return GdalDatasetPtr();
    };
    if (!QFileInfo::exists(path))
        return fail(QCoreApplication::translate("GdalDataset", "no such file"));
    // GDAL reports its reasons through the error handler; keep them for the message instead of stderr.
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    GdalDatasetPtr dataset(GDALDataset::Open(path.toUtf8().constData(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr,
                                             siblings ? siblings->names() : nullptr));
    CPLPopErrorHandler();
    if (!dataset)
        return fail(lastGdalError(QCoreApplication::translate("GdalDataset", "GDAL knows no raster format for this file")));
    if (dataset->GetRasterCount() < 1)
        return fail(QCoreApplication::translate("GdalDataset", "the file has no raster band"));
    return dataset;
}

} // namespace sortie::raster
