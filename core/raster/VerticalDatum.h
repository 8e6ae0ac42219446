#pragma once

#include <QString>

class OGRSpatialReference;

namespace sortie::raster {

// What a raster's heights are measured from, as its spatial reference says.
struct VerticalDatum
{
    enum class Kind {
        Ellipsoidal,  // WGS-84 ellipsoid (a geographic/projected 3D CRS such as EPSG:4979): converted to AMSL
        Orthometric,  // a gravity-related height (EGM96, EGM2008, a national datum): taken as AMSL
        Unstated      // the file says nothing: taken as AMSL
    };
    Kind kind = Kind::Unstated;
    QString name;  // the vertical CRS's name ("EGM96 height"), or the 3D CRS's for ellipsoidal heights

    // From a raster's SRS (null: no SRS at all).
    static VerticalDatum of(const OGRSpatialReference *srs);
    // For the log and the operator: "ellipsoidal (WGS 84)", "orthometric (EGM96 height)", "not stated".
    QString describe() const;
};

} // namespace sortie::raster
