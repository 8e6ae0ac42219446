#include "TrafficReport.h"

#include "SbsMessage.h"

namespace sortie::traffic {
namespace {
template<class T, class F>
auto mapped(const std::optional<T> &v, F f) -> std::optional<decltype(f(*v))>
{
    return v ? std::optional(f(*v)) : std::nullopt;
}
} // namespace

TrafficReport reportFromSbs(const sbs::SbsMessage &m)
{
    TrafficReport r;
    r.address = m.address;
    r.nonIcaoAddress = m.nonIcaoAddress;
    r.source = TrafficSource::Receiver;
    r.callsign = mapped(m.callsign, [](const std::string &s) { return QString::fromStdString(s); });
    r.latitude = m.latitude;
    r.longitude = m.longitude;
    r.altitudeM = mapped(m.altitudeFt, [](double ft) { return ft * kMetresPerFoot; });
    r.altitudeReference = AltitudeReference::Barometric;
    r.groundSpeedMps = mapped(m.groundSpeedKt, [](double kt) { return kt * kMetresPerSecondPerKnot; });
    r.trackDeg = m.trackDeg;
    r.verticalRateMps = mapped(m.verticalRateFpm, [](double fpm) { return fpm * kMetresPerFoot / 60.0; });
    r.squawk = mapped(m.squawk, [](const std::string &s) { return QString::fromStdString(s); });
    r.onGround = m.onGround;
    return r;
}

} // namespace sortie::traffic
