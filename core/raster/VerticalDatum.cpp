#include "VerticalDatum.h"

#include <QCoreApplication>
#include <ogr_spatialref.h>

namespace sortie::raster {

VerticalDatum VerticalDatum::of(const OGRSpatialReference *srs)
{
    if (!srs || srs->IsEmpty())
        return {};
    if (srs->IsCompound()) {
        // Geographic or projected + a vertical CRS: always gravity-related (WKT has no ellipsoidal VERTCRS).
        const char *vertical = srs->GetAttrValue("COMPD_CS|VERT_CS");
        return {Kind::Orthometric, QString::fromUtf8(vertical ? vertical : srs->GetName())};
    }
    // A third axis on a geographic or projected CRS is the ellipsoidal height (EPSG:4979 and kin).
    if ((srs->IsGeographic() || srs->IsProjected()) && srs->GetAxesCount() == 3)
        return {Kind::Ellipsoidal, QString::fromUtf8(srs->GetName())};
    return {};
}

QString VerticalDatum::describe() const
{
    switch (kind) {
    case Kind::Ellipsoidal:
        return QCoreApplication::translate("VerticalDatum", "ellipsoidal (%1)").arg(name);
    case Kind::Orthometric:
        return QCoreApplication::translate("VerticalDatum", "orthometric (%1)").arg(name);
    case Kind::Unstated:
        break;
    }
    return QCoreApplication::translate("VerticalDatum", "not stated");
}

} // namespace sortie::raster
