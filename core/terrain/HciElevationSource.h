#pragma once

#include "ElevationSource.h"

#include <QHash>
#include <QPointer>
#include <QSet>
#include <QTimer>

#include <optional>
#include <vector>
#include <QCoreApplication>

namespace sortie::hci {
class HciSession;
}

namespace sortie::terrain {

// The UgCS server's elevation (its own sources in the order its operator set) over HCI, never
// blocking: a path is asked for in one GetElevationProfileRequest (one at a time: while one is out,
// only the latest path asked for waits for its turn), points are gathered into one
// GetRasterValuesRequest per event-loop turn (in batches of kBatch). Until an answer is in, samples
// are Pending; answers are cached for the session (dropped when it is replaced or re-established)
// and announced with dataChanged(). Latitudes and longitudes travel in radians, as everywhere in
// HCI; a value the server marks as missing (NaN, or noData with no value) is NoData. While the
// session is not ready the server cannot be asked: NoData, not Pending.
class HciElevationSource : public ElevationSource
{
    Q_OBJECT

public:
    static constexpr int kBatch = 2000;
    static constexpr int kMaxCachedProfiles = 64;

    explicit HciElevationSource(hci::HciSession *session, QObject *parent = nullptr);

    QString name() const override { return QCoreApplication::translate("HciElevationSource", "UgCS server"); }
    ElevationSample sample(const GeoPoint &point) override;
    void samplePath(const SampledPath &path, std::vector<ElevationSample> &out) override;

    int requestsSent() const { return m_requests; }
    void clearCache();

private:
    static quint64 pointKey(const GeoPoint &p);
    static QByteArray pathKey(const SampledPath &path);
    void flushPoints();
    void requestProfile(const QByteArray &key, const SampledPath &path);
    void storeProfile(const QByteArray &key, std::vector<double> values);

    QPointer<hci::HciSession> m_session;
    QHash<quint64, float> m_points;  // NaN: the server has no data there
    QHash<quint64, GeoPoint> m_queued;
    QSet<quint64> m_inFlight;
    QHash<QByteArray, std::vector<double>> m_profiles;  // per path key, one value per sampled point
    QHash<QByteArray, bool> m_profilesAsked;
    bool m_profileInFlight = false;
    std::optional<SampledPath> m_nextProfile;
    QTimer m_flush;
    int m_requests = 0;
    int m_generation = 0;  // bumps on clearCache: late answers for an old session are dropped
};

} // namespace sortie::terrain
