#pragma once

#include "GeoPoint.h"

#include <optional>

namespace sortie::mission {

struct Ellipsoid
{
    double a;  // semi-major axis, metres
    double f;  // flattening
    static constexpr Ellipsoid wgs84() { return {6378137.0, 1.0 / 298.257223563}; }
};

struct GeodesicInverse
{
    double distance = 0.0;     // metres along the ellipsoid
    double azimuth1Deg = 0.0;  // forward azimuth at the first point, clockwise from north, 0..360
    double azimuth2Deg = 0.0;  // forward azimuth at the second point
};

struct GeodesicDirect
{
    GeoPoint point;
    double azimuth2Deg = 0.0;
};

// Geodesics on an ellipsoid by Vincenty's nested series (Survey Review 23(176), 1975), with the
// azimuths made continuous through the poles. Agrees with the exact geodesic to better than
// 0.5 mm for any pair of points that are not nearly antipodal. Nearly antipodal pairs (where the
// iteration does not converge) return nullopt: a route leg is never half the globe long.
std::optional<GeodesicInverse> geodesicInverse(const GeoPoint &p1, const GeoPoint &p2,
                                               const Ellipsoid &e = Ellipsoid::wgs84());
GeodesicDirect geodesicDirect(const GeoPoint &p1, double azimuthDeg, double distance,
                              const Ellipsoid &e = Ellipsoid::wgs84());
// Distance only. Legs within kShortLegDegrees in latitude and longitude (about 1 km) use the
// ellipsoidal mid-latitude formula, within 10 µm of Vincenty; nearly antipodal points fall back
// to the great circle on the mean sphere (error < 0.5 %).
constexpr double kShortLegDegrees = 0.01;
double geodesicDistance(const GeoPoint &p1, const GeoPoint &p2, const Ellipsoid &e = Ellipsoid::wgs84());

// Earth-centred, earth-fixed coordinates on WGS-84 (metres).
struct Ecef { double x = 0, y = 0, z = 0; };
Ecef toEcef(const GeoPoint &p, double height = 0.0);
GeoPoint fromEcef(const Ecef &e, double *height = nullptr);

double normalizeLongitude(double lonDeg);  // into [-180, 180)

} // namespace sortie::mission
