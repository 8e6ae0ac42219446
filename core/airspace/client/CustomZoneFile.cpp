#include "CustomZoneFile.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QCoreApplication>

namespace sortie::airspace {

namespace {
QJsonArray position(const GeoPoint &p)
{
    return QJsonArray{p.longitude, p.latitude};
}

QJsonArray ring(const std::vector<GeoPoint> &points)
{
    QJsonArray out;
    for (const GeoPoint &p : points)
        out.append(position(p));
    if (!points.empty())
        out.append(position(points.front()));  // GeoJSON rings are closed
    return out;
}

QString referenceKey(HeightReference r)
{
    return r == HeightReference::Amsl ? QStringLiteral("AMSL") : r == HeightReference::AboveTerrain ? QStringLiteral("AGL") : QStringLiteral("HOME");
}

QJsonObject feature(const Zone &z)
{
    QJsonObject properties{{QStringLiteral("name"), z.name},
                           {QStringLiteral("kind"), kindName(z.kind)},
                           {QStringLiteral("active"), z.active}};
    if (z.serverId) {  // a copy of a server zone being edited here: what sending it back updates
        properties.insert(QStringLiteral("serverId"), *z.serverId);
        properties.insert(QStringLiteral("serverVersion"), z.serverVersion);
    }
    if (z.floor)
        properties.insert(QStringLiteral("floor"), z.floor->metres);
    if (z.ceiling)
        properties.insert(QStringLiteral("ceiling"), z.ceiling->metres);
    // A drawn zone has one reference for both limits (ZoneEditor::setLimits).
    const std::optional<HeightLimit> &limit = z.floor ? z.floor : z.ceiling;
    properties.insert(QStringLiteral("reference"), referenceKey(limit ? limit->reference : HeightReference::Amsl));
    QJsonObject geometry;
    if (const auto *polygons = std::get_if<ZonePolygons>(&z.shape)) {
        QJsonArray parts;
        for (const ZonePolygon &part : polygons->parts) {
            QJsonArray rings;
            for (const auto &r : part.rings)
                rings.append(ring(r));
            parts.append(rings);
        }
        geometry = parts.size() == 1 ? QJsonObject{{QStringLiteral("type"), QStringLiteral("Polygon")}, {QStringLiteral("coordinates"), parts.first()}}
                                     : QJsonObject{{QStringLiteral("type"), QStringLiteral("MultiPolygon")}, {QStringLiteral("coordinates"), parts}};
    } else if (const auto *circle = std::get_if<ZoneCircle>(&z.shape)) {
        geometry = {{QStringLiteral("type"), QStringLiteral("Point")}, {QStringLiteral("coordinates"), position(circle->center)}};
        properties.insert(QStringLiteral("radius"), circle->radius);
    } else if (const auto *cone = std::get_if<ZoneConeFrustum>(&z.shape)) {
        geometry = {{QStringLiteral("type"), QStringLiteral("Point")}, {QStringLiteral("coordinates"), position(cone->center)}};
        properties.insert(QStringLiteral("radius"), cone->bottomRadius);
        properties.insert(QStringLiteral("topRadius"), cone->topRadius);
    }
    return {{QStringLiteral("type"), QStringLiteral("Feature")}, {QStringLiteral("geometry"), geometry}, {QStringLiteral("properties"), properties}};
}
} // namespace

QByteArray customZonesJson(const std::vector<Zone> &zones)
{
    QJsonArray features;
    for (const Zone &z : zones)
        features.append(feature(z));
    return QJsonDocument(QJsonObject{{QStringLiteral("type"), QStringLiteral("FeatureCollection")}, {QStringLiteral("features"), features}})
        .toJson(QJsonDocument::Indented);
}

bool writeCustomZones(const QString &path, const std::vector<Zone> &zones, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(customZonesJson(zones)) < 0 || !file.commit()) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

mission::Result<ZoneFile> readCustomZones(const QString &path)
{
    mission::Result<ZoneFile> read = loadZoneFile(path);
    if (!read)
        return read;
    ZoneFile out = std::move(read).value();
    for (Zone &z : out.zones) {
        z.source = ZoneSource::ServerCustom;
        z.origin = QCoreApplication::translate("CustomZoneFile", "drawn on the map");
    }
    // The server ids the GeoJSON reader does not know, by feature; only when every feature was
    // read (else which zone is which is not certain, and a draft becomes a new zone).
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return out;
    const QJsonArray features = QJsonDocument::fromJson(file.readAll()).object().value(QStringLiteral("features")).toArray();
    if (features.size() != qsizetype(out.zones.size()))
        return out;
    for (qsizetype i = 0; i < features.size(); ++i) {
        const QJsonObject properties = features[i].toObject().value(QStringLiteral("properties")).toObject();
        const QJsonValue id = properties.value(QStringLiteral("serverId"));
        if (!id.isDouble())
            continue;
        Zone &z = out.zones[size_t(i)];
        z.serverId = id.toInt();
        z.serverVersion = properties.value(QStringLiteral("serverVersion")).toInt();
        z.origin = QCoreApplication::translate("Airspace", "server zone %1, edited here").arg(*z.serverId);
    }
    return out;
}

} // namespace sortie::airspace
