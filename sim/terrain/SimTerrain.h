#pragma once

#include "ElevationSource.h"

#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace sortie::sim {

// The built-in ground: flat at `base` metres everywhere, with a few smooth hills around the demo
// area near Riga (tens of metres high, none under the vehicles' homes), so that the demo route
// has a profile. Deterministic: the same place always has the same height.
class BuiltInTerrain : public terrain::ElevationSource
{
    Q_OBJECT

public:
    struct Hill
    {
        double latitude, longitude;  // the top, degrees
        double height;               // metres above the base
        double radius;               // metres; the ground is flat beyond it
    };

    explicit BuiltInTerrain(double base, QObject *parent = nullptr);
    QString name() const override { return QStringLiteral("built-in terrain near Riga"); }
    terrain::ElevationSample sample(const terrain::GeoPoint &point) override;
    double height(double latitude, double longitude) const;
    const std::vector<Hill> &hills() const { return m_hills; }

private:
    double m_base;
    std::vector<Hill> m_hills;
};

// The simulated world's ground, one for the whole server: from a DEM (--dem: any raster GDAL reads,
// .hgt tiles, a folder) or built in.
class SimTerrain
{
public:
    // Built in, flat at `base` away from the hills.
    explicit SimTerrain(double base);
    // From a DEM file or folder (raster::openDem); nullptr with `error` when the path is not usable.
    static std::unique_ptr<SimTerrain> fromDem(const QString &path, QString *error);
    ~SimTerrain();

    terrain::ElevationSource &source() const { return *m_source; }
    QString description() const { return m_source->name(); }
    std::optional<double> groundAt(double latitude, double longitude) const;
    // The ground, or `fallback` where the data has a hole (the vehicles need somewhere to stand).
    double groundOr(double latitude, double longitude, double fallback) const;

private:
    SimTerrain() = default;
    std::unique_ptr<terrain::ElevationSource> m_source;
};

} // namespace sortie::sim
