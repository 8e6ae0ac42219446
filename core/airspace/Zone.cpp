#include "Zone.h"
#include <QCoreApplication>

namespace sortie::airspace {

QString referenceName(HeightReference reference)
{
    switch (reference) {
    case HeightReference::Amsl: return QStringLiteral("AMSL");
    case HeightReference::AboveTerrain: return QStringLiteral("AGL");
    case HeightReference::AboveHome: return QCoreApplication::translate("Zone", "above home");
    }
    return {};
}

QString kindName(ZoneKind kind)
{
    return kind == ZoneKind::Exclusion ? QStringLiteral("exclusion") : QStringLiteral("inclusion");
}

QString sourceName(ZoneSource source)
{
    switch (source) {
    case ZoneSource::File: return QStringLiteral("file");
    case ZoneSource::ServerAerodrome: return QCoreApplication::translate("Zone", "server aerodrome");
    case ZoneSource::ServerCustom: return QCoreApplication::translate("Zone", "server custom");
    case ZoneSource::VehicleFence: return QCoreApplication::translate("Zone", "vehicle fence");
    }
    return {};
}

QString limitText(const std::optional<HeightLimit> &limit, bool ceiling)
{
    if (!limit)
        return ceiling ? QStringLiteral("unlimited") : QStringLiteral("ground");
    return QStringLiteral("%1 m %2").arg(QString::number(limit->metres, 'f', limit->metres == std::floor(limit->metres) ? 0 : 1),
                                         referenceName(limit->reference));
}

std::vector<Zone> zonesOfFence(const mission::RouteFence &fence, const QString &prefix, ZoneSource source, const QString &origin)
{
    std::vector<Zone> out;
    int n = 0;
    for (const mission::FencePolygon &p : fence.polygons) {
        Zone z;
        z.name = QCoreApplication::translate("Zone", "%1 polygon %2").arg(prefix).arg(++n);
        z.kind = p.inclusion ? ZoneKind::Inclusion : ZoneKind::Exclusion;
        z.shape = ZonePolygons{{ZonePolygon{{p.vertices}}}};
        z.source = source;
        z.origin = origin;
        out.push_back(std::move(z));
    }
    n = 0;
    for (const mission::FenceCircle &c : fence.circles) {
        Zone z;
        z.name = QCoreApplication::translate("Zone", "%1 circle %2").arg(prefix).arg(++n);
        z.kind = c.inclusion ? ZoneKind::Inclusion : ZoneKind::Exclusion;
        z.shape = ZoneCircle{c.center, c.radius};
        z.source = source;
        z.origin = origin;
        out.push_back(std::move(z));
    }
    return out;
}

} // namespace sortie::airspace
