#include "ZoneFiles.h"

#include "QgcPlanFormat.h"

#include <QFile>
#include <QFileInfo>
#include <QCoreApplication>

namespace sortie::airspace {

mission::Result<ZoneFile> readPlanZones(const QByteArray &data, const QString &origin)
{
    ZoneFile out;
    const mission::Result<mission::RouteFence> fence = mission::formats::readQgcPlanFence(data, &out.problems);
    if (!fence)
        return fence.error();
    for (Zone &z : zonesOfFence(*fence, QStringLiteral("geofence"), ZoneSource::File, origin)) {
        if (const QString problem = shapeProblem(z); !problem.isEmpty())
            out.problems << QCoreApplication::translate("ZoneFiles", "%1 was left out: %2").arg(z.name, problem);
        else
            out.zones.push_back(std::move(z));
    }
    return out;
}

mission::Result<ZoneFile> loadZoneFile(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    mission::Result<ZoneFile> (*reader)(const QByteArray &, const QString &) = nullptr;
    if (suffix == QLatin1String("plan"))
        reader = readPlanZones;
    else if (suffix == QLatin1String("geojson") || suffix == QLatin1String("json"))
        reader = readGeoJsonZones;
    else if (suffix == QLatin1String("kml"))
        reader = readKmlZones;
    else
        return mission::MissionError{QCoreApplication::translate("ZoneFiles", "unknown zone file type \".%1\" (Sortie reads .plan, .geojson, .json and .kml)").arg(suffix),
                                     path, 0, 0, {}};
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return mission::MissionError{f.errorString(), path, 0, 0, {}};
    mission::Result<ZoneFile> read = reader(f.readAll(), QFileInfo(path).fileName());
    if (!read)
        return read.error().withFile(path);
    return read;
}

} // namespace sortie::airspace
