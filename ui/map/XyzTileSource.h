#pragma once

#include "TileSource.h"

#include <QDeadlineTimer>
#include <QHash>
#include <QList>

class QNetworkAccessManager;
class QNetworkDiskCache;
class QNetworkReply;

namespace sortie::ui {

// Tiles from a web server through an XYZ URL template such as
// "https://tile.example.org/{z}/{x}/{y}.png" ({-y} counts rows from the south, {s} picks one
// of `subdomains`). Tiles go through an on-disk cache (QNetworkDiskCache); when the server
// cannot be reached the source serves what the cache holds, says it is unreachable, and probes
// the server again every `retryInterval` ms so the map recovers by itself.
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

public:
    explicit XyzTileSource(QObject *parent = nullptr);
    ~XyzTileSource() override;

    QString urlTemplate() const { return m_template; }
    void setUrlTemplate(const QString &urlTemplate);
    QString subdomains() const { return m_subdomains; }
    void setSubdomains(const QString &subdomains);
    QString cacheDirectory() const;
    void setCacheDirectory(const QString &directory);
    int maximumConcurrentRequests() const { return m_maxConcurrent; }
    void setMaximumConcurrentRequests(int count);
    int retryInterval() const { return m_retryMs; }
    void setRetryInterval(int milliseconds) { m_retryMs = milliseconds; }
    int loadingCount() const { return int(m_queue.size() + m_active.size()); }

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

private:
    enum class Mode { Network, CacheOnly };
    void startNext();
    void start(const TileKey &key, Mode mode);
    void finished(QNetworkReply *reply);
    void networkFailed(const TileKey &key, const QString &reason);
    void invalidateAll();
    void updateName();

    QNetworkAccessManager *m_network;
    QNetworkDiskCache *m_diskCache;
    QString m_template;
    QString m_subdomains = QStringLiteral("abc");
    QString m_autoName;
    QString m_cacheDirectory;
    int m_maxConcurrent = 6;
    int m_retryMs = 15000;
    QList<TileKey> m_queue;                    // newest last: served first
    QHash<QNetworkReply *, TileKey> m_active;
    QDeadlineTimer m_nextProbe{QDeadlineTimer::Forever};
    bool m_probing = false;
};

} // namespace sortie::ui
