#include "Geodesy.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::mission {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kMaxIterations = 200;
constexpr double kTolerance = 1e-12;  // radians on the auxiliary sphere: ~0.006 mm

double azimuthDeg(double radians)
{
    double d = radians / kDeg;
    d = std::fmod(d, 360.0);
    if (d < 0)
        d += 360.0;
    return d;
}

// Reduced latitude, computed so that it stays exact at the poles.
void reduced(double latRad, double f, double *sinU, double *cosU)
{
    const double u = std::atan2((1.0 - f) * std::sin(latRad), std::cos(latRad));
    *sinU = std::sin(u);
    *cosU = std::cos(u);
}

// Vincenty's series for the length of the geodesic on the auxiliary sphere.
void series(double cos2Alpha, double a, double b, double *A, double *B)
{
    const double u2 = cos2Alpha * (a * a - b * b) / (b * b);
    *A = 1 + u2 / 16384 * (4096 + u2 * (-768 + u2 * (320 - 175 * u2)));
    *B = u2 / 1024 * (256 + u2 * (-128 + u2 * (74 - 47 * u2)));
}

double deltaSigma(double B, double sinSigma, double cosSigma, double cos2SigmaM)
{
    const double c2 = cos2SigmaM * cos2SigmaM;
    return B * sinSigma * (cos2SigmaM + B / 4 * (cosSigma * (-1 + 2 * c2)
        - B / 6 * cos2SigmaM * (-3 + 4 * sinSigma * sinSigma) * (-3 + 4 * c2)));
}
}

double normalizeLongitude(double lonDeg)
{
    double l = std::fmod(lonDeg + 180.0, 360.0);
    if (l < 0)
        l += 360.0;
    return l - 180.0;
}

std::optional<GeodesicInverse> geodesicInverse(const GeoPoint &p1, const GeoPoint &p2, const Ellipsoid &e)
{
    const double a = e.a, f = e.f, b = a * (1 - f);
    const double L = normalizeLongitude(p2.longitude - p1.longitude) * kDeg;
    double sinU1, cosU1, sinU2, cosU2;
    reduced(p1.latitude * kDeg, f, &sinU1, &cosU1);
    reduced(p2.latitude * kDeg, f, &sinU2, &cosU2);

    double lambda = L, sinLambda = 0, cosLambda = 1;
    double sinSigma = 0, cosSigma = 1, sigma = 0, cos2Alpha = 1, cos2SigmaM = 0;
    int i = 0;
    for (; i < kMaxIterations; ++i) {
        sinLambda = std::sin(lambda);
        cosLambda = std::cos(lambda);
        const double t1 = cosU2 * sinLambda;
        const double t2 = cosU1 * sinU2 - sinU1 * cosU2 * cosLambda;
        sinSigma = std::sqrt(t1 * t1 + t2 * t2);
        if (sinSigma == 0)
            return GeodesicInverse{0.0, 0.0, 0.0};  // coincident points
        cosSigma = sinU1 * sinU2 + cosU1 * cosU2 * cosLambda;
        sigma = std::atan2(sinSigma, cosSigma);
        const double sinAlpha = cosU1 * cosU2 * sinLambda / sinSigma;
        cos2Alpha = 1 - sinAlpha * sinAlpha;
        cos2SigmaM = cos2Alpha != 0 ? cosSigma - 2 * sinU1 * sinU2 / cos2Alpha : 0.0;  // 0 on the equator
        const double C = f / 16 * cos2Alpha * (4 + f * (4 - 3 * cos2Alpha));
        const double previous = lambda;
        lambda = L + (1 - C) * f * sinAlpha
            * (sigma + C * sinSigma * (cos2SigmaM + C * cosSigma * (-1 + 2 * cos2SigmaM * cos2SigmaM)));
        if (std::abs(lambda) > std::numbers::pi)
            return std::nullopt;  // nearly antipodal: the series diverges
        if (std::abs(lambda - previous) < kTolerance)
            break;
    }
    if (i == kMaxIterations)
        return std::nullopt;

    double A, B;
    series(cos2Alpha, a, b, &A, &B);
    const double s = b * A * (sigma - deltaSigma(B, sinSigma, cosSigma, cos2SigmaM));
    const double alpha1 = std::atan2(cosU2 * sinLambda, cosU1 * sinU2 - sinU1 * cosU2 * cosLambda);
    const double alpha2 = std::atan2(cosU1 * sinLambda, -sinU1 * cosU2 + cosU1 * sinU2 * cosLambda);
    return GeodesicInverse{s, azimuthDeg(alpha1), azimuthDeg(alpha2)};
}

GeodesicDirect geodesicDirect(const GeoPoint &p1, double azimuthDeg1, double distance, const Ellipsoid &e)
{
    const double a = e.a, f = e.f, b = a * (1 - f);
    const double alpha1 = azimuthDeg1 * kDeg;
    const double sinAlpha1 = std::sin(alpha1), cosAlpha1 = std::cos(alpha1);
    double sinU1, cosU1;
    reduced(p1.latitude * kDeg, f, &sinU1, &cosU1);
    const double sigma1 = std::atan2(sinU1, cosU1 * cosAlpha1);
    const double sinAlpha = cosU1 * sinAlpha1;
    const double cos2Alpha = 1 - sinAlpha * sinAlpha;
    double A, B;
    series(cos2Alpha, a, b, &A, &B);

    double sigma = distance / (b * A);
    double sinSigma = 0, cosSigma = 1, cos2SigmaM = 0;
    for (int i = 0; i < kMaxIterations; ++i) {
        cos2SigmaM = std::cos(2 * sigma1 + sigma);
        sinSigma = std::sin(sigma);
        cosSigma = std::cos(sigma);
        const double previous = sigma;
        sigma = distance / (b * A) + deltaSigma(B, sinSigma, cosSigma, cos2SigmaM);
        if (std::abs(sigma - previous) < kTolerance)
            break;
    }
    sinSigma = std::sin(sigma);
    cosSigma = std::cos(sigma);
    cos2SigmaM = std::cos(2 * sigma1 + sigma);

    const double x = sinU1 * sinSigma - cosU1 * cosSigma * cosAlpha1;
    const double lat2 = std::atan2(sinU1 * cosSigma + cosU1 * sinSigma * cosAlpha1,
                                   (1 - f) * std::sqrt(sinAlpha * sinAlpha + x * x));
    const double lambda = std::atan2(sinSigma * sinAlpha1, cosU1 * cosSigma - sinU1 * sinSigma * cosAlpha1);
    const double C = f / 16 * cos2Alpha * (4 + f * (4 - 3 * cos2Alpha));
    const double L = lambda - (1 - C) * f * sinAlpha
        * (sigma + C * sinSigma * (cos2SigmaM + C * cosSigma * (-1 + 2 * cos2SigmaM * cos2SigmaM)));
    GeodesicDirect out;
    out.point.latitude = lat2 / kDeg;
    out.point.longitude = normalizeLongitude(p1.longitude + L / kDeg);
    out.azimuth2Deg = azimuthDeg(std::atan2(sinAlpha, -x));
    return out;
}

double geodesicDistance(const GeoPoint &p1, const GeoPoint &p2, const Ellipsoid &e)
{
    const double dLat = p2.latitude - p1.latitude;
    const double dLon = normalizeLongitude(p2.longitude - p1.longitude);
    if (std::abs(dLat) <= kShortLegDegrees && std::abs(dLon) <= kShortLegDegrees) {
        // Short leg: the ellipsoid's meridian and prime-vertical radii at the mid-latitude. Agrees
        // with Vincenty to 10 µm within 0.01° (tests/mission/tst_geodesy), at a tenth of the cost.
        const double e2 = e.f * (2 - e.f);
        const double mid = (p1.latitude + dLat / 2) * kDeg;
        const double s = std::sin(mid), w = 1 - e2 * s * s;
        const double m = e.a * (1 - e2) / (w * std::sqrt(w)), n = e.a / std::sqrt(w);
        return std::hypot(m * dLat * kDeg, n * std::cos(mid) * dLon * kDeg);
    }
    if (auto g = geodesicInverse(p1, p2, e))
        return g->distance;
    // Nearly antipodal: great-circle distance on the sphere of the same mean radius.
    const double r = e.a * (1 - e.f / 3);
    const double phi1 = p1.latitude * kDeg, phi2 = p2.latitude * kDeg;
    const double dl = (p2.longitude - p1.longitude) * kDeg;
    const double c = std::sin(phi1) * std::sin(phi2) + std::cos(phi1) * std::cos(phi2) * std::cos(dl);
    return r * std::acos(std::clamp(c, -1.0, 1.0));
}

Ecef toEcef(const GeoPoint &p, double height)
{
    const Ellipsoid e = Ellipsoid::wgs84();
    const double e2 = e.f * (2 - e.f);
    const double lat = p.latitude * kDeg, lon = p.longitude * kDeg;
    const double sinLat = std::sin(lat), cosLat = std::cos(lat);
    const double n = e.a / std::sqrt(1 - e2 * sinLat * sinLat);
    return {(n + height) * cosLat * std::cos(lon), (n + height) * cosLat * std::sin(lon),
            (n * (1 - e2) + height) * sinLat};
}

GeoPoint fromEcef(const Ecef &v, double *height)
{
    // Bowring's formula: micrometre accuracy for points near the surface.
    const Ellipsoid e = Ellipsoid::wgs84();
    const double a = e.a, b = a * (1 - e.f);
    const double e2 = e.f * (2 - e.f), ep2 = (a * a - b * b) / (b * b);
    const double p = std::hypot(v.x, v.y);
    const double theta = std::atan2(v.z * a, p * b);
    const double st = std::sin(theta), ct = std::cos(theta);
    const double lat = std::atan2(v.z + ep2 * b * st * st * st, p - e2 * a * ct * ct * ct);
    const double lon = std::atan2(v.y, v.x);
    if (height) {
        const double sinLat = std::sin(lat);
        *height = p * std::cos(lat) + v.z * sinLat - a * std::sqrt(1 - e2 * sinLat * sinLat);
    }
    return {lat / kDeg, lon / kDeg};
}

} // namespace sortie::mission
