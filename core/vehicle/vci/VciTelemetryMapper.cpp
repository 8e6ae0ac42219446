#include "VciTelemetryMapper.h"

#include "VciProfile.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

namespace sortie::vehicle {
namespace {

namespace profile = vci::profile;
using F = TelemetryField;

struct Mapping
{
    std::string_view uri;
    std::array<std::pair<const char *, TelemetryField>, 4> fields;
    size_t count;
};

const std::array<Mapping, 6> kObjects = {{
    {profile::kPosition, {{{"latitude", F::Latitude}, {"longitude", F::Longitude}, {"altitudeAmsl", F::AltitudeAmsl}, {"altitudeAgl", F::AltitudeAgl}}}, 4},
    {profile::kAttitude, {{{"roll", F::Roll}, {"pitch", F::Pitch}, {"yaw", F::Heading}, {"", F::Count_}}}, 3},
    {profile::kSpeed, {{{"ground", F::GroundSpeed}, {"air", F::AirSpeed}, {"vertical", F::VerticalSpeed}, {"course", F::Course}}}, 4},
    {profile::kBattery, {{{"voltage", F::BatteryVoltage}, {"current", F::BatteryCurrent}, {"remaining", F::BatteryRemaining}, {"", F::Count_}}}, 3},
    {profile::kGps, {{{"fix", F::GpsFix}, {"satellites", F::Satellites}, {"hdop", F::Hdop}, {"", F::Count_}}}, 3},
    {profile::kHome, {{{"latitude", F::HomeLatitude}, {"longitude", F::HomeLongitude}, {"altitudeAmsl", F::HomeAltitudeAmsl}, {"", F::Count_}}}, 3},
}};

// A body's "time" (ms since the epoch) when it is a number an int64 holds; `now` otherwise. A
// floating-point time out of that range would be undefined behaviour to convert (fuzz_vci_telemetry).
int64_t timeOf(const nlohmann::json &body, int64_t now)
{
    if (!body.is_object())
        return now;
    const auto t = body.find("time");
    if (t == body.end())
        return now;
    if (t->is_number_integer())
        return t->is_number_unsigned() && t->get<uint64_t>() > uint64_t(std::numeric_limits<int64_t>::max()) ? now : t->get<int64_t>();
    if (t->is_number_float()) {
        const double ms = t->get<double>();
        return std::isfinite(ms) && std::abs(ms) < 9.0e18 ? int64_t(ms) : now;
    }
    return now;
}

// A value the vehicle sent, converted; none when it is not finite (a number JSON holds can still
// overflow when converted to degrees).
std::optional<double> valueOf(TelemetryField field, double value)
{
    const double converted = isAngle(field) ? degreesFromRadians(value) : value;
    return std::isfinite(converted) ? std::optional<double>(converted) : std::nullopt;
}

} // namespace

TelemetryBatch vciTelemetry(std::string_view uri, const nlohmann::json &body, int64_t now)
{
    TelemetryBatch out;
    const int64_t time = timeOf(body, now);
    for (const Mapping &m : kObjects) {
        if (m.uri != uri)
            continue;
        if (!body.is_object())
            return out;
        for (size_t i = 0; i < m.count; ++i) {
            const auto it = body.find(m.fields[i].first);
            if (it == body.end() || !it->is_number())
                continue;
            const TelemetryField field = m.fields[i].second;
            if (const auto value = valueOf(field, it->get<double>()))
                out.push_back({field, *value, time});
        }
        return out;
    }
    if (uri == profile::kArmed && body.is_boolean()) {
        out.push_back({F::Armed, body.get<bool>() ? 1.0 : 0.0, time});
    } else if (uri == profile::kMode && body.is_string()) {
        out.push_back({F::Mode, double(modeFromName(body.get<std::string>())), time});
    } else if (uri == profile::kFenceStatus && body.is_object()) {
        // "none" and "clear" are both not breached; a count the vehicle leaves out stays unknown.
        const auto state = body.find("state");
        if (state != body.end() && state->is_string())
            out.push_back({F::FenceBreach, state->get<std::string>() == "breached" ? 1.0 : 0.0, time});
        const auto breaches = body.find("breaches");
        if (breaches != body.end() && breaches->is_number())
            out.push_back({F::FenceBreaches, breaches->get<double>(), time});
    } else if (uri == profile::kMissionProgress && body.is_object()) {
        const auto state = body.find("state");
        if (state != body.end() && state->is_string()) {
            if (const auto s = missionStateFromName(state->get<std::string>()))
                out.push_back({F::MissionState, double(*s), time});
        }
        for (const auto &[key, field] : {std::pair{"current", F::MissionCurrent}, {"reached", F::MissionReached}, {"count", F::MissionCount}}) {
            const auto it = body.find(key);
            if (it != body.end() && it->is_number())
                out.push_back({field, it->get<double>(), time});
        }
    }
    return out;
}

} // namespace sortie::vehicle
