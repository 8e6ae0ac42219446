#include "HciTelemetryMapper.h"

#include "Domain.pb.h"

#include <cmath>
#include <optional>

namespace sortie::vehicle {
namespace {

namespace pb = com::ugcs::ucs::proto;
using F = TelemetryField;

std::optional<double> number(const pb::Value &v)
{
    if (v.has_floatvalue()) return double(v.floatvalue());
    if (v.has_doublevalue()) return v.doublevalue();
    if (v.has_intvalue()) return double(v.intvalue());
    if (v.has_longvalue()) return double(v.longvalue());
    if (v.has_boolvalue()) return v.boolvalue() ? 1.0 : 0.0;
    return std::nullopt;
}

std::optional<TelemetryField> fieldFor(const pb::TelemetryField &f)
{
    switch (f.semantic()) {
    case pb::S_LATITUDE: return F::Latitude;
    case pb::S_LONGITUDE: return F::Longitude;
    case pb::S_ALTITUDE_AMSL: return F::AltitudeAmsl;
    case pb::S_ALTITUDE_AGL: return F::AltitudeAgl;
    case pb::S_HEADING: return F::Heading;
    case pb::S_YAW: return F::Heading;
    case pb::S_ROLL: return F::Roll;
    case pb::S_PITCH: return F::Pitch;
    case pb::S_GROUND_SPEED: return F::GroundSpeed;
    case pb::S_AIR_SPEED: return F::AirSpeed;
    case pb::S_VERTICAL_SPEED: return F::VerticalSpeed;
    case pb::S_VOLTAGE: return F::BatteryVoltage;
    case pb::S_CURRENT: return F::BatteryCurrent;
    case pb::S_CAPACITY_LEVEL: return F::BatteryRemaining;
    case pb::S_SATELLITE_COUNT: return F::Satellites;
    case pb::S_GPS_FIX_TYPE: return F::GpsFix;
    case pb::S_FLIGHT_MODE: return F::Mode;
    case pb::S_BOOL:
        if (f.code() == "is_armed" || f.code() == "armed")
            return F::Armed;
        return std::nullopt;
    default:
        return std::nullopt;
    }
}

} // namespace

void appendHciTelemetry(const pb::Telemetry &t, int64_t now, TelemetryBatch &out)
{
    const int64_t time = t.has_time() ? t.time() : now;
    const pb::TelemetryField &f = t.telemetryfield();
    if (f.has_subsystem() && f.subsystem() != pb::S_FLIGHT_CONTROLLER)
        return;
    const auto field = fieldFor(f);
    if (!field)
        return;
    const pb::Value &v = t.value();
    if (*field == F::Mode) {
        if (v.has_stringvalue())
            out.push_back({F::Mode, double(modeFromName(v.stringvalue())), time});
        return;
    }
    auto value = number(v);
    if (!value)
        return; // "value unavailable"
    if (*field == F::BatteryRemaining)
        *value /= 100.0;
    else if (isAngle(*field))
        *value = degreesFromRadians(*value);
    if (!std::isfinite(*value))
        return; // NaN or infinity on the wire (or once converted) is no reading (fuzz_hci_telemetry)
    out.push_back({*field, *value, time});
}

std::optional<std::string> hciVideoStreamUri(const pb::TelemetryEvent &event)
{
    std::optional<std::string> uri;
    for (const pb::Telemetry &t : event.telemetry())
        if (t.telemetryfield().code() == "video_stream_uri" && t.value().has_stringvalue())
            uri = t.value().stringvalue();
    return uri;
}

TelemetryBatch hciTelemetry(const pb::TelemetryEvent &event, int64_t now)
{
    TelemetryBatch out;
    out.reserve(size_t(event.telemetry_size()));
    for (const pb::Telemetry &t : event.telemetry())
        appendHciTelemetry(t, now, out);
    return out;
}

} // namespace sortie::vehicle
