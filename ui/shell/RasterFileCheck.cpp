#include "RasterFileCheck.h"

#include "DemOpener.h"
#include "OrthophotoRenderer.h"

#include <QUrl>

namespace sortie::ui {

QString RasterFileCheck::localPath(const QString &pathOrUrl)
{
    return pathOrUrl.startsWith(QLatin1String("file:")) ? QUrl(pathOrUrl).toLocalFile() : pathOrUrl;
}

QString RasterFileCheck::demProblem(const QString &path) const
{
    const QString local = localPath(path.trimmed());
    if (local.isEmpty())
        return {};
    QString error;
    return raster::openDem(local, &error) ? QString() : error;
}

QString RasterFileCheck::orthophotoProblem(const QString &path) const
{
    const QString local = localPath(path.trimmed());
    if (local.isEmpty())
        return {};
    QString error;
    return raster::OrthophotoRenderer::open(local, &error) ? QString() : error;
}

} // namespace sortie::ui
