#include "XyzTileSource.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <QNetworkAccessManager>
#include <QNetworkDiskCache>
#include <QNetworkReply>
#include <QStandardPaths>
#include <QUrl>

Q_LOGGING_CATEGORY(lcTiles, "sortie.ui.tiles")

namespace sortie::ui {

namespace {
constexpr auto kModeProperty = "sortieCacheOnly";
constexpr qint64 kDiskCacheBytes = 512ll * 1024 * 1024;
constexpr int kTransferTimeoutMs = 10000;
} // namespace

XyzTileSource::XyzTileSource(QObject *parent)
    : TileSource(parent)
    , m_network(new QNetworkAccessManager(this))
    , m_diskCache(new QNetworkDiskCache(this))
{
    setInfo(tr("Web tiles"), {}, 0, 19);
    m_diskCache->setMaximumCacheSize(kDiskCacheBytes);
    m_diskCache->setCacheDirectory(cacheDirectory());
    m_network->setCache(m_diskCache);
    connect(m_network, &QNetworkAccessManager::finished, this, &XyzTileSource::finished);
    setReachable(false, validateTemplate(m_template));
}

XyzTileSource::~XyzTileSource()
{
    // Replies finishing during destruction must not reach a half-destroyed source.
    disconnect(m_network, nullptr, this, nullptr);
}

QString XyzTileSource::validateTemplate(const QString &urlTemplate)
{
    if (urlTemplate.trimmed().isEmpty())
        return tr("No tile URL template is set.");
    QString sample = urlTemplate;
    for (const char *field : {"{z}", "{x}", "{y}", "{-y}"})
        sample.replace(QLatin1String(field), QLatin1String("0"));
    sample.replace(QLatin1String("{s}"), QLatin1String("a"));
    const QUrl url(sample, QUrl::StrictMode);
    if (!url.isValid())
        return tr("The tile URL template is not a valid URL: %1").arg(url.errorString());
    const QString scheme = url.scheme().toLower();
    if (scheme != QLatin1String("http") && scheme != QLatin1String("https") && scheme != QLatin1String("file"))
        return tr("The tile URL template must start with http://, https:// or file://.");
    const bool hasY = urlTemplate.contains(QLatin1String("{y}")) || urlTemplate.contains(QLatin1String("{-y}"));
    if (!urlTemplate.contains(QLatin1String("{z}")) || !urlTemplate.contains(QLatin1String("{x}")) || !hasY)
        return tr("The tile URL template needs {z}, {x} and {y} (or {-y}).");
    return {};
}

void XyzTileSource::setUrlTemplate(const QString &urlTemplate)
{
    if (urlTemplate == m_template)
        return;
    m_template = urlTemplate;
    const QString problem = validateTemplate(m_template);
    updateName();
    m_nextProbe = QDeadlineTimer(0);
    m_probing = false;
    setReachable(problem.isEmpty(), problem);
    invalidateAll();
    emit urlTemplateChanged();
}

void XyzTileSource::updateName()
{
    // Named after the server unless someone named it.
    if (name() != m_autoName && name() != tr("Web tiles"))
        return;
    m_autoName = tileUrl({0, 0, 0}).host();
    setName(m_autoName.isEmpty() ? tr("Web tiles") : m_autoName);
}

void XyzTileSource::setSubdomains(const QString &subdomains)
{
    if (subdomains == m_subdomains)
        return;
    m_subdomains = subdomains;
    updateName();
    invalidateAll();
    emit urlTemplateChanged();
}

QString XyzTileSource::cacheDirectory() const
{
    if (!m_cacheDirectory.isEmpty())
        return m_cacheDirectory;
    return QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QLatin1String("/tiles");
}

void XyzTileSource::setCacheDirectory(const QString &directory)
{
    if (directory == m_cacheDirectory)
        return;
    m_cacheDirectory = directory;
    m_diskCache->setCacheDirectory(cacheDirectory());
    emit cacheDirectoryChanged();
}

void XyzTileSource::setMaximumConcurrentRequests(int count)
{
    m_maxConcurrent = std::max(1, count);
    startNext();
}

QUrl XyzTileSource::tileUrl(const TileKey &key) const
{
    if (!validateTemplate(m_template).isEmpty() || !key.isValid())
        return {};
    QString text = m_template;
    text.replace(QLatin1String("{z}"), QString::number(key.z));
    text.replace(QLatin1String("{x}"), QString::number(key.x));
    text.replace(QLatin1String("{y}"), QString::number(key.y));
    text.replace(QLatin1String("{-y}"), QString::number((1 << key.z) - 1 - key.y));
    if (!m_subdomains.isEmpty())
        text.replace(QLatin1String("{s}"), m_subdomains.at((key.x + key.y) % m_subdomains.size()));
    return QUrl(text, QUrl::TolerantMode);
}

void XyzTileSource::requestTile(const TileKey &key)
{
    const QString problem = validateTemplate(m_template);
    if (!problem.isEmpty()) {
        QMetaObject::invokeMethod(this, [this, key, problem] { emit tileFailed(key, problem); }, Qt::QueuedConnection);
        return;
    }
    m_queue.removeAll(key);
    m_queue.append(key);
    emit loadingCountChanged();
    startNext();
}

QList<TileKey> XyzTileSource::cancelPending()
{
    QList<TileKey> cancelled;
    cancelled.swap(m_queue);
    if (!cancelled.isEmpty())
        emit loadingCountChanged();
    return cancelled;
}

void XyzTileSource::startNext()
{
    while (!m_queue.isEmpty() && m_active.size() < m_maxConcurrent) {
        const TileKey key = m_queue.takeLast();
        if (isReachable()) {
            start(key, Mode::Network);
        } else if (!m_probing && m_nextProbe.hasExpired()) {
            // One request at a time finds out whether the server is back.
            m_probing = true;
            start(key, Mode::Network);
        } else {
            start(key, Mode::CacheOnly);
        }
    }
}

void XyzTileSource::start(const TileKey &key, Mode mode)
{
    QNetworkRequest request(tileUrl(key));
    request.setHeader(QNetworkRequest::UserAgentHeader,
                      QStringLiteral("Sortie/%1 (mission planner)").arg(QCoreApplication::applicationVersion()));
    request.setAttribute(QNetworkRequest::CacheLoadControlAttribute,
                         mode == Mode::CacheOnly ? QNetworkRequest::AlwaysCache : QNetworkRequest::PreferCache);
    request.setAttribute(QNetworkRequest::RedirectPolicyAttribute, QNetworkRequest::NoLessSafeRedirectPolicy);
    request.setTransferTimeout(kTransferTimeoutMs);
    QNetworkReply *reply = m_network->get(request);
    reply->setProperty(kModeProperty, mode == Mode::CacheOnly);
    m_active.insert(reply, key);
}

void XyzTileSource::finished(QNetworkReply *reply)
{
    reply->deleteLater();
    const auto it = m_active.find(reply);
    if (it == m_active.end())
        return;
    const TileKey key = it.value();
    m_active.erase(it);
    const bool cacheOnly = reply->property(kModeProperty).toBool();
    const QVariant status = reply->attribute(QNetworkRequest::HttpStatusCodeAttribute);
    const bool isFile = reply->url().isLocalFile();

    if (reply->error() == QNetworkReply::NoError) {
        const QImage image = QImage::fromData(reply->readAll());
        if (!cacheOnly) {
            m_probing = false;
            setReachable(true);
        }
        if (image.isNull())
            emit tileFailed(key, tr("Tile %1 is not an image.").arg(key.toString()));
        else
            emit tileReady(key, image.convertToFormat(QImage::Format_ARGB32_Premultiplied));
    } else if (cacheOnly) {
        emit tileFailed(key, tr("Tile %1 is not in the cache and the tile server is unreachable.").arg(key.toString()));
    } else if (status.isValid() || isFile) {
        // The server answered: this tile is missing, the server is fine.
        m_probing = false;
        setReachable(true);
        emit tileFailed(key, isFile ? tr("No tile file %1.").arg(reply->url().toLocalFile())
                                    : tr("The tile server answered HTTP %1 for tile %2.").arg(status.toInt()).arg(key.toString()));
    } else {
        networkFailed(key, reply->errorString());
    }
    emit loadingCountChanged();
    startNext();
}

void XyzTileSource::networkFailed(const TileKey &key, const QString &reason)
{
    if (isReachable())
        qCInfo(lcTiles) << "tile server unreachable:" << reason;
    m_probing = false;
    m_nextProbe = QDeadlineTimer(m_retryMs);
    setReachable(false, tr("Tile server unreachable (%1).").arg(reason));
    // What the disk cache holds is still good for an operator without a network.
    start(key, Mode::CacheOnly);
}

void XyzTileSource::invalidateAll()
{
    m_queue.clear();
    const auto replies = m_active.keys();
    m_active.clear();
    for (QNetworkReply *reply : replies)
        reply->abort(); // no longer in m_active: finished() ignores it
    emit loadingCountChanged();
    emit invalidated();
}

} // namespace sortie::ui
