#include "HciElevationSource.h"

#include "Geodesy.h"
#include "HciReply.h"
#include "HciSession.h"
#include "Messages.pb.h"
#include "ServerProfile.h"
#include "TerrainLog.h"

#include <QCryptographicHash>

#include <cmath>
#include <limits>
#include <numbers>

namespace sortie::terrain {

namespace pb = com::ugcs::ucs::proto;

namespace {
constexpr double kRad = std::numbers::pi / 180.0;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
}

HciElevationSource::HciElevationSource(hci::HciSession *session, QObject *parent)
    : ElevationSource(parent), m_session(session)
{
    m_flush.setSingleShot(true);
    m_flush.setInterval(0);
    connect(&m_flush, &QTimer::timeout, this, &HciElevationSource::flushPoints);
    if (session) {
        // A new or re-established session may see other data (the server's sources can change meanwhile).
        connect(session, &hci::HciSession::ready, this, [this] {
            clearCache();
            emit dataChanged();
        });
        connect(session, &hci::HciSession::resumed, this, [this] {
            clearCache();
            emit dataChanged();
        });
    }
}

void HciElevationSource::clearCache()
{
    ++m_generation;
    m_points.clear();
    m_queued.clear();
    m_inFlight.clear();
    m_profiles.clear();
    m_profilesAsked.clear();
    m_profileInFlight = false;
    m_nextProfile.reset();
}

quint64 HciElevationSource::pointKey(const GeoPoint &p)
{
    // 1e-6° (about 0.1 m): the same place asked twice is one question.
    const auto lat = quint64(qint64(std::llround((p.latitude + 90.0) * 1e6)));
    const auto lon = quint64(qint64(std::llround((p.longitude + 180.0) * 1e6)));
    return lat << 32 | lon;
}

QByteArray HciElevationSource::pathKey(const SampledPath &path)
{
    QCryptographicHash h(QCryptographicHash::Sha1);
    h.addData(QByteArrayView(reinterpret_cast<const char *>(&path.step), sizeof path.step));
    h.addData(QByteArrayView(reinterpret_cast<const char *>(path.vertices.data()), qsizetype(path.vertices.size() * sizeof(GeoPoint))));
    return h.result();
}

ElevationSample HciElevationSource::sample(const GeoPoint &point)
{
    if (!point.isValid() || !m_session || !m_session->isReady())
        return ElevationSample::noData();
    const quint64 key = pointKey(point);
    if (const auto it = m_points.constFind(key); it != m_points.cend())
        return std::isnan(*it) ? ElevationSample::noData() : ElevationSample::value(*it);
    if (!m_inFlight.contains(key) && !m_queued.contains(key)) {
        m_queued.insert(key, point);
        if (!m_flush.isActive())
            m_flush.start();
    }
    return ElevationSample::pending();
}

void HciElevationSource::flushPoints()
{
    if (!m_session || m_queued.isEmpty())
        return;
    pb::GetRasterValuesRequest request;
    auto keys = std::make_shared<std::vector<quint64>>();
    for (auto it = m_queued.begin(); it != m_queued.end() && int(keys->size()) < kBatch;) {
        request.add_latitudes(it.value().latitude * kRad);
        request.add_longitudes(it.value().longitude * kRad);
        keys->push_back(it.key());
        m_inFlight.insert(it.key());
        it = m_queued.erase(it);
    }
    if (!m_queued.isEmpty())
        m_flush.start();  // the rest on the next turn
    ++m_requests;
    hci::HciReply *reply = m_session->send(request);
    const int generation = m_generation;
    connect(reply, &hci::HciReply::finished, this, [this, reply, keys, generation] {
        if (generation != m_generation)
            return;
        const auto &r = reply->response<pb::GetRasterValuesResponse>();
        if (!reply->isOk())
            qCWarning(lcTerrain).noquote() << "the server did not give elevations:" << reply->error().message();
        for (size_t i = 0; i < keys->size(); ++i) {
            float v = kNaN;
            if (reply->isOk() && int(i) < r.values_size() && std::isfinite(r.values(int(i))))
                v = r.values(int(i));
            m_inFlight.remove((*keys)[i]);
            m_points.insert((*keys)[i], v);
        }
        emit dataChanged();
    });
}

void HciElevationSource::samplePath(const SampledPath &path, std::vector<ElevationSample> &out)
{
    out.assign(path.points.size(), ElevationSample::noData());
    if (path.points.empty() || !m_session || !m_session->isReady())
        return;
    const QByteArray key = pathKey(path);
    if (const auto it = m_profiles.constFind(key); it != m_profiles.cend()) {
        const std::vector<double> &values = *it;
        for (size_t i = 0; i < out.size() && i < values.size(); ++i)
            out[i] = std::isnan(values[i]) ? ElevationSample::noData() : ElevationSample::value(values[i]);
        return;
    }
    out.assign(path.points.size(), ElevationSample::pending());
    if (m_profilesAsked.contains(key))
        return;
    if (m_profileInFlight) {
        // One profile at a time: while a drag changes the path every frame, only the latest waits.
        m_nextProfile = path;
        return;
    }
    requestProfile(key, path);
}

void HciElevationSource::requestProfile(const QByteArray &key, const SampledPath &path)
{
    m_profilesAsked.insert(key, true);
    m_profileInFlight = true;
    pb::GetElevationProfileRequest request;
    request.set_samplingstep(path.step);
    for (const GeoPoint &v : path.vertices) {
        auto *l = request.add_locations();
        l->set_latitude(v.latitude * kRad);
        l->set_longitude(v.longitude * kRad);
        l->set_altitude(0.0);
        l->set_altitudetype(pb::AT_WGS84);
    }
    ++m_requests;
    hci::HciReply *reply = m_session->send(request);
    const int generation = m_generation;
    connect(reply, &hci::HciReply::finished, this, [this, reply, key, path, generation] {
        if (generation != m_generation)
            return;
        m_profileInFlight = false;
        if (!reply->isOk())
            qCWarning(lcTerrain).noquote() << "the server did not give an elevation profile:" << reply->error().message();
        storeProfile(key, reply->isOk() ? profileAlong(path, reply->response<pb::GetElevationProfileResponse>())
                                        : std::vector<double>(path.points.size(), std::numeric_limits<double>::quiet_NaN()));
        if (m_nextProfile && m_session && m_session->isReady()) {
            const SampledPath next = std::move(*m_nextProfile);
            m_nextProfile.reset();
            const QByteArray nextKey = pathKey(next);
            if (!m_profiles.contains(nextKey))
                requestProfile(nextKey, next);
        }
        emit dataChanged();
    });
}

void HciElevationSource::storeProfile(const QByteArray &key, std::vector<double> values)
{
    if (m_profiles.size() >= kMaxCachedProfiles) {
        m_profiles.clear();
        m_profilesAsked.clear();
    }
    m_profiles.insert(key, std::move(values));
    m_profilesAsked.remove(key);
}

} // namespace sortie::terrain
