#include "HciTrafficSource.h"

#include "HciClient.h"
#include "HciReply.h"
#include "HciSession.h"
#include "Messages.pb.h"
#include "TrafficLog.h"
#include "TrafficPicture.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::traffic {
namespace pb = com::ugcs::ucs::proto;
namespace {
constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

std::optional<double> finite(bool has, double v)
{
    return has && std::isfinite(v) ? std::optional(v) : std::nullopt;
}
} // namespace

HciTrafficSource::HciTrafficSource(hci::HciClient *client, TrafficPicture *picture, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_picture(picture)
{
    m_timer.setInterval(kRefreshMs);
    connect(&m_timer, &QTimer::timeout, this, &HciTrafficSource::refresh);
    m_timer.start();
    connect(m_client->session(), &hci::HciSession::stateChanged, this, [this](hci::HciSession::State state) {
        if (state == hci::HciSession::State::Ready)
            refresh();
        else
            setState(State::Idle);
    });
}

void HciTrafficSource::setArea(double latitude, double longitude, double radiusM)
{
    if (!std::isfinite(latitude) || !std::isfinite(longitude) || std::abs(latitude) > 90 || std::abs(longitude) > 180)
        return;
    const bool first = !m_hasArea;
    m_hasArea = true;
    m_latitude = latitude;
    m_longitude = longitude;
    m_radiusM = std::isfinite(radiusM) ? std::clamp(radiusM, kMinRadiusM, kMaxRadiusM) : kMinRadiusM;
    if (first)
        refresh();
}

void HciTrafficSource::refresh()
{
    if (!m_hasArea || m_pending || !m_client->session()->isReady())
        return;
    pb::GetAdsbAircraftListRequest request;
    request.set_clientid(-1);
    auto *location = request.mutable_location();
    location->set_latitude(m_latitude / kDegreesPerRadian);
    location->set_longitude(m_longitude / kDegreesPerRadian);
    location->set_altitude(0);
    location->set_altitudetype(pb::AT_WGS84);
    request.set_radius(m_radiusM);
    request.set_height(kHeightM);
    hci::HciReply *reply = m_client->session()->send(request);
    m_pending = reply;
    connect(reply, &hci::HciReply::finished, this, [this, reply] { onFinished(reply); });
    if (m_state != State::Answered)
        setState(State::Asking);
}

void HciTrafficSource::onFinished(hci::HciReply *reply)
{
    m_pending = nullptr;
    if (!reply->isOk()) {
        qCWarning(lcTraffic).noquote() << "server traffic:" << reply->error().toString();
        setState(State::Failed, reply->error().message());
        return;
    }
    const auto &response = reply->response<pb::GetAdsbAircraftListResponse>();
    int count = 0;
    for (const pb::AdsbAircraft &aircraft : response.aircrafts()) {
        if (const auto report = reportFromAdsb(aircraft)) {
            m_picture->report(*report);
            ++count;
        }
    }
    m_lastCount = count;
    setState(State::Answered);
    emit stateChanged(); // the count
    emit answered();
}

std::optional<TrafficReport> HciTrafficSource::reportFromAdsb(const pb::AdsbAircraft &a)
{
    if (!a.has_icaoaddress())
        return std::nullopt;
    TrafficReport r;
    r.source = TrafficSource::Server;
    r.address = quint32(a.icaoaddress()) & 0xffffffu;
    if (a.has_identification() && !QString::fromStdString(a.identification()).trimmed().isEmpty())
        r.callsign = QString::fromStdString(a.identification()).trimmed().left(8);
    const auto lat = finite(a.has_latitude(), a.latitude() * kDegreesPerRadian);
    const auto lon = finite(a.has_longitude(), a.longitude() * kDegreesPerRadian);
    if (lat && lon && std::abs(*lat) <= 90 && std::abs(*lon) <= 180) {
        r.latitude = lat;
        r.longitude = lon;
    }
    r.altitudeM = finite(a.has_mslaltitude(), a.mslaltitude());
    r.altitudeReference = AltitudeReference::MeanSeaLevel;
    if (const auto heading = finite(a.has_heading(), a.heading() * kDegreesPerRadian))
        r.trackDeg = std::fmod(std::fmod(*heading, 360.0) + 360.0, 360.0);
    r.groundSpeedMps = finite(a.has_groundspeed() && a.groundspeed() >= 0, a.groundspeed());
    r.verticalRateMps = finite(a.has_verticalvelocity(), a.verticalvelocity());
    if (a.has_updatetime())
        r.sourceTimeMs = a.updatetime();
    return r;
}

void HciTrafficSource::setState(State state, const QString &error)
{
    if (state == m_state && error == m_error)
        return;
    m_state = state;
    m_error = error;
    emit stateChanged();
}

} // namespace sortie::traffic
