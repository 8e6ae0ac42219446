#include "SimTelemetry.h"

#include "Messages.pb.h"

#include <cmath>

namespace sortie::sim {
namespace {

constexpr double kRad = 3.14159265358979323846 / 180.0;

pb::Telemetry *add(google::protobuf::RepeatedPtrField<pb::Telemetry> *out, qint64 time, const char *code, pb::Semantic semantic)
{
    auto *t = out->Add();
    t->set_time(time);
    auto *field = t->mutable_telemetryfield();
    field->set_code(code);
    field->set_semantic(semantic);
    field->set_subsystem(pb::S_FLIGHT_CONTROLLER);
    field->set_subsystemid(0);
    return t;
}

void appendFast(google::protobuf::RepeatedPtrField<pb::Telemetry> *out, qint64 time, const FlightModel::State &s)
{
    add(out, time, "latitude", pb::S_LATITUDE)->mutable_value()->set_doublevalue(s.latitude * kRad);
    add(out, time, "longitude", pb::S_LONGITUDE)->mutable_value()->set_doublevalue(s.longitude * kRad);
    add(out, time, "altitude_amsl", pb::S_ALTITUDE_AMSL)->mutable_value()->set_floatvalue(float(s.altitudeAmsl()));
    add(out, time, "altitude_agl", pb::S_ALTITUDE_AGL)->mutable_value()->set_floatvalue(float(s.altitudeAgl));
    add(out, time, "ground_speed", pb::S_GROUND_SPEED)->mutable_value()->set_floatvalue(float(s.groundSpeed));
    add(out, time, "vertical_speed", pb::S_VERTICAL_SPEED)->mutable_value()->set_floatvalue(float(s.verticalSpeed));
    add(out, time, "heading", pb::S_HEADING)->mutable_value()->set_floatvalue(float(s.heading * kRad));
    add(out, time, "roll", pb::S_ROLL)->mutable_value()->set_floatvalue(float(s.roll * kRad));
    add(out, time, "pitch", pb::S_PITCH)->mutable_value()->set_floatvalue(float(s.pitch * kRad));
}

void appendSlow(google::protobuf::RepeatedPtrField<pb::Telemetry> *out, qint64 time, const FlightModel::State &s)
{
    add(out, time, "battery_voltage", pb::S_VOLTAGE)->mutable_value()->set_floatvalue(float(std::round(s.batteryVoltage * 100) / 100));
    add(out, time, "battery_current", pb::S_CURRENT)->mutable_value()->set_floatvalue(float(std::round(s.batteryCurrent * 100) / 100));
    add(out, time, "battery_level", pb::S_CAPACITY_LEVEL)->mutable_value()->set_floatvalue(float(std::round(s.batteryRemaining * 10000) / 100));
    add(out, time, "gps_fix_type", pb::S_GPS_FIX_TYPE)->mutable_value()->set_intvalue(s.gpsFix);
    add(out, time, "satellite_count", pb::S_SATELLITE_COUNT)->mutable_value()->set_intvalue(s.satellites);
    add(out, time, "control_mode", pb::S_CONTROL_MODE)->mutable_value()->set_intvalue(SimTelemetry::controlMode(s.mode));
    add(out, time, "is_armed", pb::S_BOOL)->mutable_value()->set_boolvalue(s.armed);
    add(out, time, "flight_mode", pb::S_FLIGHT_MODE)->mutable_value()->set_stringvalue(SimTelemetry::flightMode(s.mode));
}

// The camera's stream (UgCS's video_stream_uri, camera subsystem), with the slow fields.
void appendCamera(google::protobuf::RepeatedPtrField<pb::Telemetry> *out, qint64 time, const std::string &uri)
{
    if (uri.empty())
        return;
    auto *t = add(out, time, "video_stream_uri", pb::S_STRING);
    t->mutable_telemetryfield()->set_subsystem(pb::S_CAMERA);
    t->mutable_value()->set_stringvalue(uri);
}

} // namespace

SimTelemetry::SimTelemetry(double rateHz, size_t historyCapacity)
    : m_rateHz(rateHz)
    , m_capacity(historyCapacity)
{
}

int SimTelemetry::controlMode(FlightModel::Mode mode)
{
    switch (mode) {
    case FlightModel::Mode::Manual: return 0;
    case FlightModel::Mode::Guided: return 2;
    default: return 1;
    }
}

const char *SimTelemetry::flightMode(FlightModel::Mode mode)
{
    switch (mode) {
    case FlightModel::Mode::Manual: return "MANUAL";
    case FlightModel::Mode::Hold: return "HOLD";
    case FlightModel::Mode::Takeoff: return "TAKEOFF";
    case FlightModel::Mode::Auto: return "AUTO";
    case FlightModel::Mode::Guided: return "GUIDED";
    case FlightModel::Mode::Land: return "LAND";
    case FlightModel::Mode::ReturnHome: return "RTL";
    }
    return "UNKNOWN";
}

void SimTelemetry::record(qint64 timeMs, const FlightModel::State &state, pb::TelemetryEvent *event)
{
    m_history.push_back({timeMs, state});
    if (m_history.size() > m_capacity)
        m_history.pop_front();

    appendFast(event->mutable_telemetry(), timeMs, state);
    const Slow slow{std::round(state.batteryVoltage * 100) / 100, std::round(state.batteryCurrent * 100) / 100,
                    std::round(state.batteryRemaining * 10000) / 100, state.satellites, state.gpsFix,
                    controlMode(state.mode), state.armed, state.mode};
    if (!(slow == m_lastSlow) || timeMs - m_lastSlowTime >= 1000) {
        appendSlow(event->mutable_telemetry(), timeMs, state);
        appendCamera(event->mutable_telemetry(), timeMs, m_videoStreamUri);
        m_lastSlow = slow;
        m_lastSlowTime = timeMs;
    }
}

void SimTelemetry::history(qint64 fromMs, qint64 toMs, int limit, pb::GetTelemetryResponse *out) const
{
    int count = 0;
    for (const Sample &sample : m_history) {
        if (sample.time < fromMs || sample.time > toMs)
            continue;
        if (count > 0 && count + kFieldCount > limit) {
            out->set_nexttelemetrytime(sample.time);
            return;
        }
        appendFast(out->mutable_telemetry(), sample.time, sample.state);
        appendSlow(out->mutable_telemetry(), sample.time, sample.state);
        count += kFieldCount;
        while (out->telemetry_size() > limit)
            out->mutable_telemetry()->RemoveLast();
    }
}

} // namespace sortie::sim
