#include "RasterFileCheck.h"

#include "DemOpener.h"
#include "OrthophotoRenderer.h"

#include <QUrl>

#include <algorithm>
#include <memory>

namespace sortie::ui {

QString RasterFileCheck::localPath(const QString &pathOrUrl)
{
    return pathOrUrl.startsWith(QLatin1String("file:")) ? QUrl(pathOrUrl).toLocalFile() : pathOrUrl;
}

DemCheck RasterFileCheck::checkDem(const QString &path) const
{
    DemCheck check;
    const QString local = localPath(path.trimmed());
    if (local.isEmpty())
        return check;
    const std::unique_ptr<terrain::ElevationSource> dem = raster::openDem(local, &check.problem);
    if (!dem)
        return check;
    // Opening a folder reads every file's header: those it could not read are known now.
    // A national DEM with many bad files is named by its first few; the log holds them all.
    constexpr qsizetype shown = 5;
    if (const QStringList problems = dem->problems(); !problems.isEmpty()) {
        check.leftOut = tr("%n file(s) left out, the others are used:", "", int(problems.size()))
                        + QLatin1Char('\n') + problems.first(std::min(shown, problems.size())).join(QLatin1Char('\n'));
        if (problems.size() > shown)
            check.leftOut += QLatin1Char('\n') + tr("and %n more (in the log)", "", int(problems.size() - shown));
    }
    return check;
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
