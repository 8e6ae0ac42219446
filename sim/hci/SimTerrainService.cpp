#include "SimTerrainService.h"

#include "HciRequestDispatcher.h"
#include "Messages.pb.h"
#include "PathSampling.h"
#include "SimTerrain.h"
#include "SimWorld.h"

#include <cmath>
#include <limits>

namespace sortie::sim {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool onGlobe(double latDeg, double lonDeg)
{
    return std::isfinite(latDeg) && std::isfinite(lonDeg) && std::abs(latDeg) <= 90 && std::abs(lonDeg) <= 180;
}

// The sampled path for a profile request, or an error for the caller.
template<class Request>
std::optional<terrain::SampledPath> pathOf(const Request &r, QString *error)
{
    if (!(r.samplingstep() > 0) || !std::isfinite(r.samplingstep())) {
        *error = QStringLiteral("samplingStep must be a positive number of metres, not %1").arg(r.samplingstep());
        return std::nullopt;
    }
    if (r.locations_size() == 0) {
        *error = QStringLiteral("An elevation profile needs at least one location");
        return std::nullopt;
    }
    std::vector<terrain::GeoPoint> vertices;
    for (int i = 0; i < r.locations_size(); ++i) {
        const double lat = r.locations(i).latitude() * kDeg, lon = r.locations(i).longitude() * kDeg;
        if (!onGlobe(lat, lon)) {
            *error = QStringLiteral("Location %1 is not on the globe (latitude and longitude are in radians)").arg(i + 1);
            return std::nullopt;
        }
        vertices.push_back({lat, lon});
    }
    double length = 0;
    for (size_t i = 1; i < vertices.size(); ++i)
        length += terrain::samplePath({vertices[i - 1], vertices[i]}, 1e9).length();
    if (length / r.samplingstep() + double(vertices.size()) > SimTerrainService::kMaxSamples) {
        *error = QStringLiteral("The profile would have more than %1 samples: use a larger samplingStep").arg(SimTerrainService::kMaxSamples);
        return std::nullopt;
    }
    return terrain::samplePath(std::move(vertices), r.samplingstep());
}

template<class Response>
void fillProfile(const terrain::SampledPath &path, const SimTerrain &terrain, Response &out, bool v2)
{
    for (const terrain::PathSamplePoint &p : path.points) {
        const auto ground = terrain.groundAt(p.position.latitude, p.position.longitude);
        auto *l = out.add_locations();
        l->set_latitude(p.position.latitude / kDeg);
        l->set_longitude(p.position.longitude / kDeg);
        l->set_altitude(ground.value_or(kNaN));
        l->set_altitudetype(pb::AT_WGS84);
        out.add_elevations(ground.value_or(kNaN));
        out.add_obstacleheight(0.0);
        if constexpr (requires { out.add_accumulateddistances(0.0); }) {
            if (v2) {
                out.add_accumulateddistances(p.distance);
                out.add_surfaceheight(ground.value_or(kNaN));
            }
        }
    }
}

} // namespace

void SimTerrainService::install(HciRequestDispatcher &d, SimWorld &world)
{
    using A = HciRequestDispatcher::Access;
    d.add(pb::GetElevationProfileRequest::default_instance(), A::LoggedIn, [&world](SimCall &c) {
        QString error;
        const auto path = pathOf(static_cast<const pb::GetElevationProfileRequest &>(c.request), &error);
        if (!path)
            return c.respond.error(error);
        pb::GetElevationProfileResponse out;
        fillProfile(*path, world.terrain(), out, false);
        c.respond.reply(out);
    });
    d.add(pb::GetElevationProfileV2Request::default_instance(), A::LoggedIn, [&world](SimCall &c) {
        QString error;
        const auto path = pathOf(static_cast<const pb::GetElevationProfileV2Request &>(c.request), &error);
        if (!path)
            return c.respond.error(error);
        pb::GetElevationProfileV2Response out;
        fillProfile(*path, world.terrain(), out, true);
        c.respond.reply(out);
    });
    d.add(pb::GetRasterValuesRequest::default_instance(), A::LoggedIn, [&world](SimCall &c) {
        const auto &r = static_cast<const pb::GetRasterValuesRequest &>(c.request);
        if (r.latitudes_size() != r.longitudes_size())
            return c.respond.error(QStringLiteral("%1 latitudes but %2 longitudes").arg(r.latitudes_size()).arg(r.longitudes_size()));
        if (r.latitudes_size() > kMaxSamples)
            return c.respond.error(QStringLiteral("More than %1 points in one request").arg(kMaxSamples));
        pb::GetRasterValuesResponse out;
        bool missing = false;
        for (int i = 0; i < r.latitudes_size(); ++i) {
            const double lat = r.latitudes(i) * kDeg, lon = r.longitudes(i) * kDeg;
            const auto ground = onGlobe(lat, lon) ? world.terrain().groundAt(lat, lon) : std::nullopt;
            missing |= !ground;
            out.add_values(float(ground.value_or(kNaN)));
        }
        out.set_nodata(missing);
        c.respond.reply(out);
    });
    d.add(pb::GetRasterGridRequest::default_instance(), A::LoggedIn, [&world](SimCall &c) {
        const auto &r = static_cast<const pb::GetRasterGridRequest &>(c.request);
        const double south = r.minlatitude() * kDeg, west = r.minlongitude() * kDeg;
        const double north = r.maxlatitude() * kDeg, east = r.maxlongitude() * kDeg;
        if (r.width() < 1 || r.height() < 1 || qint64(r.width()) * r.height() > kMaxSamples)
            return c.respond.error(QStringLiteral("A grid of %1×%2 is not between 1 and %3 values").arg(r.width()).arg(r.height()).arg(kMaxSamples));
        if (!onGlobe(south, west) || !onGlobe(north, east) || north < south)
            return c.respond.error(QStringLiteral("The box is not on the globe (radians, min below max)"));
        pb::GetRasterGridResponse out;
        out.set_width(r.width());
        out.set_height(r.height());
        bool missing = false;
        for (int row = 0; row < r.height(); ++row) {
            const double lat = r.height() == 1 ? (south + north) / 2 : north - (north - south) * row / (r.height() - 1);
            for (int col = 0; col < r.width(); ++col) {
                const double lon = r.width() == 1 ? (west + east) / 2 : west + (east - west) * col / (r.width() - 1);
                const auto ground = world.terrain().groundAt(lat, lon);
                missing |= !ground;
                out.add_values(float(ground.value_or(kNaN)));
            }
        }
        out.set_nodata(missing);
        c.respond.reply(out);
    });
}

} // namespace sortie::sim
