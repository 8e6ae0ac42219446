#pragma once

#include "FlightModel.h"
#include "HciProto.h"

#include <QtGlobal>

#include <deque>
#include <string>

namespace com::ugcs::ucs::proto {
class TelemetryEvent;
class GetTelemetryResponse;
} // namespace com::ugcs::ucs::proto

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;

// A vehicle's telemetry as UgCS sends it: TelemetryField codes and semantics as the server uses them
// (latitude/longitude in radians as doubles, altitudes and speeds in metres as floats, heading in
// radians, is_armed as bool, flight_mode as string...), times in ms since the epoch. Batches are
// incremental: position, altitude and speeds every tick; battery, GPS, mode and arming when they change
// and at least once a second. Keeps a bounded history for GetTelemetry.
class SimTelemetry
{
public:
    explicit SimTelemetry(double rateHz, size_t historyCapacity = 6000);

    // Records one tick and fills `event` (whose vehicle is set by the caller) with this batch.
    void record(qint64 timeMs, const FlightModel::State &state, pb::TelemetryEvent *event);
    // Every field of every recorded sample in [fromMs, toMs], at most `limit` values. Sets
    // nextTelemetryTime to the first sample left out, when some were.
    void history(qint64 fromMs, qint64 toMs, int limit, pb::GetTelemetryResponse *out) const;
    size_t samples() const { return m_history.size(); }
    // The camera's stream, sent with the slow fields as `video_stream_uri` (camera subsystem); empty: none.
    void setVideoStreamUri(const std::string &uri) { m_videoStreamUri = uri; }

    static int controlMode(FlightModel::Mode mode);   // 0 manual, 1 automatic, 2 click & go
    static const char *flightMode(FlightModel::Mode mode);
    static constexpr int kFieldCount = 17;

private:
    struct Sample
    {
        qint64 time;
        FlightModel::State state;
    };
    struct Slow
    {
        double voltage = -1, current = -1, percent = -1;
        int satellites = -1, fix = -1, control = -1;
        bool armed = false;
        FlightModel::Mode mode = FlightModel::Mode::Manual;
        bool operator==(const Slow &) const = default;
    };

    double m_rateHz;
    size_t m_capacity;
    std::deque<Sample> m_history;
    Slow m_lastSlow;
    qint64 m_lastSlowTime = 0;
    std::string m_videoStreamUri;
};

} // namespace sortie::sim
