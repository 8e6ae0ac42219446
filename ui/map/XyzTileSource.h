#pragma once

#include "TileSource.h"
#include "TileUrlTemplate.h"

#include <QDeadlineTimer>
#include <QHash>
#include <QList>
#include <QSet>

class QNetworkAccessManager;
class QNetworkDiskCache;
class QNetworkReply;

namespace sortie::ui {

// Tiles from a web server through an XYZ URL template such as
// "https://tile.example.org/{z}/{x}/{y}.png" ({-y} counts rows from the south, {s} picks one
// of `subdomains`). Tiles go through an on-disk cache (QNetworkDiskCache); when the server
// cannot be reached the source serves what the cache holds, says it is unreachable, and probes
// the server again every `retryInterval` ms so the map recovers by itself. Tiles taken offline
// for this server (`packFile`, an MBTiles file the prefetch wrote) are served first; with
// `cacheOnly` the network is never used: the pack, then the disk cache, else the base map.
class MbTilesTileSource;

class XyzTileSource : public TileSource
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QString urlTemplate READ urlTemplate WRITE setUrlTemplate NOTIFY urlTemplateChanged)
    Q_PROPERTY(QString subdomains READ subdomains WRITE setSubdomains NOTIFY urlTemplateChanged)
    Q_PROPERTY(QString cacheDirectory READ cacheDirectory WRITE setCacheDirectory NOTIFY cacheDirectoryChanged)
    Q_PROPERTY(int maximumConcurrentRequests READ maximumConcurrentRequests WRITE setMaximumConcurrentRequests)
    Q_PROPERTY(int retryInterval READ retryInterval WRITE setRetryInterval)
    Q_PROPERTY(int loadingCount READ loadingCount NOTIFY loadingCountChanged)
    Q_PROPERTY(QString packFile READ packFile WRITE setPackFile NOTIFY packChanged)
    Q_PROPERTY(bool cacheOnly READ cacheOnly WRITE setCacheOnly NOTIFY packChanged)

public:
    explicit XyzTileSource(QObject *parent = nullptr);
    ~XyzTileSource() override;

    QString urlTemplate() const { return m_template.pattern(); }
    void setUrlTemplate(const QString &urlTemplate);
    QString subdomains() const { return m_template.subdomains(); }
    void setSubdomains(const QString &subdomains);
    QString cacheDirectory() const;
    void setCacheDirectory(const QString &directory);
    int maximumConcurrentRequests() const { return m_maxConcurrent; }
    void setMaximumConcurrentRequests(int count);
    int retryInterval() const { return m_retryMs; }
    void setRetryInterval(int milliseconds) { m_retryMs = milliseconds; }
    int loadingCount() const { return int(m_queue.size() + m_active.size() + m_packPending.size()) + m_decoding; }
    QString packFile() const;
    void setPackFile(const QString &file);
    bool cacheOnly() const { return m_cacheOnly; }
    void setCacheOnly(bool cacheOnly);

    // The URL of one tile, or an empty URL when the template is not usable.
    QUrl tileUrl(const TileKey &key) const;
    // Checks a template; returns an operator-readable reason when it cannot work.
    static QString validateTemplate(const QString &urlTemplate);

    void requestTile(const TileKey &key) override;
    QList<TileKey> cancelPending() override;

signals:
    void urlTemplateChanged();
    void cacheDirectoryChanged();
    void loadingCountChanged();
    void packChanged();

private:
    enum class Mode { Network, CacheOnly };
    void startNext();
    void start(const TileKey &key, Mode mode);
    void finished(QNetworkReply *reply);
    void networkFailed(const TileKey &key, const QString &reason);
    void invalidateAll();
    void updateName();
    void packTileReady(const TileKey &key, const QImage &image);
    void packTileFailed(const TileKey &key);
    void queueForNetwork(const TileKey &key);
    void decode(const TileKey &key, QByteArray bytes);

    QNetworkAccessManager *m_network;
    QNetworkDiskCache *m_diskCache;
    maptiles::TileUrlTemplate m_template;
    MbTilesTileSource *m_pack;
    QSet<TileKey> m_packPending;
    QDeadlineTimer m_nextPackCheck;
    bool m_cacheOnly = false;
    QString m_autoName;
    QString m_cacheDirectory;
    int m_maxConcurrent = 6;
    int m_retryMs = 15000;
    QList<TileKey> m_queue;                    // newest last: served first
    QHash<QNetworkReply *, TileKey> m_active;
    QDeadlineTimer m_nextProbe{QDeadlineTimer::Forever};
    bool m_probing = false;
    int m_decoding = 0;          // tiles being decoded on the thread pool
    quint64 m_generation = 0;    // invalidateAll() makes decodes still running stale
};

} // namespace sortie::ui
