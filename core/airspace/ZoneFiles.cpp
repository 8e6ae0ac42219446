#include "ZoneFiles.h"

#include "MissionFiles.h"

#include "GeoZoneReader.h"
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

ZoneFile zonesOfGeoZones(const ed::GeoZoneFile &file, const QString &origin)
{
    ZoneFile out;
    out.problems = file.problems;
    for (const ed::GeoZone &g : file.zones) {
        const auto shared = std::make_shared<const ed::GeoZone>(g);
        const auto limitOf = [](const std::optional<ed::VerticalLimit> &l) -> std::optional<HeightLimit> {
            if (!l)
                return std::nullopt;
            return HeightLimit{l->metres, l->reference == ed::VerticalReference::Agl ? HeightReference::AboveTerrain : HeightReference::Amsl};
        };
        std::vector<Zone> volumes;
        QString problem;
        for (size_t i = 0; i < g.volumes.size() && problem.isEmpty(); ++i) {
            const ed::Volume &v = g.volumes[i];
            Zone z;
            z.name = g.name;
            z.kind = ZoneKind::Exclusion;
            if (v.circle) {
                z.shape = ZoneCircle{v.circle->center, v.circle->radius};
            } else {
                ZonePolygons parts;
                for (const ed::Polygon &p : v.polygons)
                    parts.parts.push_back(ZonePolygon{p.rings});
                z.shape = std::move(parts);
            }
            z.floor = limitOf(v.lower);
            z.ceiling = limitOf(v.upper);
            z.source = ZoneSource::File;
            z.origin = origin.isEmpty() ? g.identifier : QStringLiteral("%1, %2").arg(origin, g.identifier);
            z.geoZone = shared;
            z.volume = int(i) + 1;
            problem = shapeProblem(z);
            if (!problem.isEmpty())
                problem = QCoreApplication::translate("ZoneFiles", "volume %1: %2").arg(i + 1).arg(problem);
            volumes.push_back(std::move(z));
        }
        if (!problem.isEmpty()) {
            out.problems << QCoreApplication::translate("ZoneFiles", "%1 zone %2 ('%3') was left out: %4")
                                .arg(ed::formatName(file.format), g.identifier, g.name, problem);
            continue;
        }
        out.zones.insert(out.zones.end(), std::make_move_iterator(volumes.begin()), std::make_move_iterator(volumes.end()));
    }
    return out;
}

mission::Result<ZoneFile> readZoneData(const QByteArray &data, const QString &name)
{
    if (std::optional<mission::Result<ed::GeoZoneFile>> geo = ed::readGeoZones(data)) {
        if (!*geo)
            return geo->error();
        return zonesOfGeoZones(geo->value(), name);
    }
    const QString suffix = QFileInfo(name).suffix().toLower();
    if (suffix == QLatin1String("plan"))
        return readPlanZones(data, name);
    if (suffix == QLatin1String("geojson") || suffix == QLatin1String("json"))
        return readGeoJsonZones(data, name);
    if (suffix == QLatin1String("kml"))
        return readKmlZones(data, name);
    return mission::MissionError{QCoreApplication::translate("ZoneFiles", "unknown zone file type \".%1\" (Sortie reads .plan, .geojson, .json and .kml)").arg(suffix),
                                 {}, 0, 0, {}};
}

mission::Result<ZoneFile> loadZoneFile(const QString &path)
{
    // A national zone file is a few MB (Switzerland's 1,200 zones: 2.8 MB); 64 MiB bounds a hostile one.
    const mission::Result<QByteArray> data = mission::formats::readFileAtMost(path, 64 * 1024 * 1024);
    if (!data)
        return data.error();
    mission::Result<ZoneFile> read = readZoneData(data.value(), QFileInfo(path).fileName());
    if (!read)
        return read.error().withFile(path);
    return read;
}

} // namespace sortie::airspace
