#include "SimTerrain.h"

#include "DemOpener.h"
#include "HgtTileSource.h"

#include <cmath>
#include <numbers>

namespace sortie::sim {

namespace {
constexpr double kMetresPerDegree = 111320.0;
}

BuiltInTerrain::BuiltInTerrain(double base, QObject *parent)
    : terrain::ElevationSource(parent), m_base(base)
{
    // The demo route's first leg crosses a 20 m knoll between its first two waypoints; two larger
    // hills lie a kilometre and more from the vehicles' homes (56.975–56.978 N, 24.073–24.079 E).
    m_hills = {
        {56.97725, 24.07475, 20.0, 120.0},
        {56.99000, 24.06000, 60.0, 600.0},
        {56.96500, 24.10000, 40.0, 500.0},
        {56.98500, 24.09500, 30.0, 350.0},
    };
}

double BuiltInTerrain::height(double latitude, double longitude) const
{
    double h = m_base;
    const double cosLat = std::cos(latitude * std::numbers::pi / 180.0);
    for (const Hill &hill : m_hills) {
        const double dy = (latitude - hill.latitude) * kMetresPerDegree;
        const double dx = (longitude - hill.longitude) * kMetresPerDegree * cosLat;
        const double d = std::hypot(dx, dy);
        if (d >= hill.radius)
            continue;
        const double c = std::cos(0.5 * std::numbers::pi * d / hill.radius);  // a smooth bell, flat at its edge
        h += hill.height * c * c;
    }
    return h;
}

terrain::ElevationSample BuiltInTerrain::sample(const terrain::GeoPoint &p)
{
    if (!p.isValid())
        return terrain::ElevationSample::noData();
    return terrain::ElevationSample::value(height(p.latitude, p.longitude));
}

SimTerrain::SimTerrain(double base) : m_source(std::make_unique<BuiltInTerrain>(base)) {}

SimTerrain::~SimTerrain() = default;

std::unique_ptr<SimTerrain> SimTerrain::fromDem(const QString &path, QString *error)
{
    QString why;
    std::unique_ptr<terrain::ElevationSource> dem = raster::openDem(path, &why);
    // A folder with nothing to read would be a world without ground.
    if (auto *tiles = qobject_cast<terrain::HgtTileSource *>(dem.get()); tiles && tiles->tileCount() == 0)
        why = QStringLiteral("%1: no DEM there (no SRTM tile NxxEyyy.hgt, no raster GDAL reads)").arg(path), dem.reset();
    if (!dem) {
        if (error)
            *error = why;
        return nullptr;
    }
    std::unique_ptr<SimTerrain> t(new SimTerrain);
    t->m_source = std::move(dem);
    return t;
}

std::optional<double> SimTerrain::groundAt(double latitude, double longitude) const
{
    const terrain::ElevationSample s = m_source->sample({latitude, longitude});
    return s.hasValue() ? std::optional<double>(s.ground) : std::nullopt;
}

double SimTerrain::groundOr(double latitude, double longitude, double fallback) const
{
    return groundAt(latitude, longitude).value_or(fallback);
}

} // namespace sortie::sim
