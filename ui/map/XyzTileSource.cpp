#include "XyzTileSource.h"

#include "MbTilesTileSource.h"
#include "TilePrefetch.h"
#include "TileResponse.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLoggingCategory>
#include <QNetworkAccessManager>
#include <QNetworkDiskCache>
#include <QNetworkReply>
#include <QStandardPaths>
#include <QFutureWatcher>
#include <QUrl>
#include <QtConcurrent/QtConcurrentRun>

Q_LOGGING_CATEGORY(lcTiles, "sortie.ui.tiles")

namespace sortie::ui {

namespace {
constexpr auto kModeProperty = "sortieCacheOnly";
constexpr qint64 kDiskCacheBytes = 512ll * 1024 * 1024;
constexpr int kTransferTimeoutMs = 10000;
constexpr int kPackCheckMs = 5000;
} // namespace

XyzTileSource::XyzTileSource(QObject *parent)
    : TileSource(parent)
    , m_network(new QNetworkAccessManager(this))
    , m_diskCache(new QNetworkDiskCache(this))
    , m_pack(new MbTilesTileSource(this))
{
    connect(m_pack, &TileSource::tileReady, this, &XyzTileSource::packTileReady);
    connect(m_pack, &TileSource::tileFailed, this, [this](const TileKey &key) { packTileFailed(key); });
    setInfo(tr("Web tiles"), {}, 0, 19);
    m_diskCache->setMaximumCacheSize(kDiskCacheBytes);
    m_diskCache->setCacheDirectory(cacheDirectory());
    m_network->setCache(m_diskCache);
    connect(m_network, &QNetworkAccessManager::finished, this, &XyzTileSource::finished);
    setReachable(false, validateTemplate(urlTemplate()));
}

XyzTileSource::~XyzTileSource()
{
    // Replies finishing during destruction must not reach a half-destroyed source.
    disconnect(m_network, nullptr, this, nullptr);
}

QString XyzTileSource::validateTemplate(const QString &urlTemplate)
{
    return maptiles::TileUrlTemplate::validate(urlTemplate);
}

void XyzTileSource::setUrlTemplate(const QString &urlTemplate)
{
    if (urlTemplate == m_template.pattern())
        return;
    m_template = maptiles::TileUrlTemplate(urlTemplate, m_template.subdomains());
    const QString problem = m_template.problem();
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
    if (subdomains == m_template.subdomains())
        return;
    m_template = maptiles::TileUrlTemplate(m_template.pattern(), subdomains);
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
    return m_template.url({key.z, key.x, key.y});
}

QString XyzTileSource::packFile() const
{
    return m_pack->file();
}

void XyzTileSource::setPackFile(const QString &file)
{
    if (file == m_pack->file())
        return;
    m_pack->setFile(file);
    // The pack keeps the provider's attribution: shown when nobody set one.
    if (attribution().isEmpty() && m_pack->isValid())
        setAttribution(m_pack->attribution());
    invalidateAll();
    emit packChanged();
}

void XyzTileSource::setCacheOnly(bool cacheOnly)
{
    if (cacheOnly == m_cacheOnly)
        return;
    m_cacheOnly = cacheOnly;
    invalidateAll();
    emit packChanged();
}

void XyzTileSource::requestTile(const TileKey &key)
{
    if (!m_pack->isValid() && !m_pack->file().isEmpty() && m_nextPackCheck.hasExpired()) {
        // The pack may have been written since it was set (a download just made it).
        m_nextPackCheck.setRemainingTime(kPackCheckMs);
        if (QFileInfo::exists(m_pack->file())) {
            m_pack->reopen();
            // Tiles that failed before the pack was there are asked for again (after this request).
            if (m_pack->isValid())
                QMetaObject::invokeMethod(this, &XyzTileSource::invalidated, Qt::QueuedConnection);
        }
    }
    if (m_pack->isValid()) {
        // The offline pack first: what was taken offline never costs a request.
        m_packPending.insert(key);
        m_pack->requestTile(key);
        emit loadingCountChanged();
        return;
    }
    queueForNetwork(key);
}

void XyzTileSource::packTileReady(const TileKey &key, const QImage &image)
{
    if (!m_packPending.remove(key))
        return;
    emit loadingCountChanged();
    emit tileReady(key, image);
}

void XyzTileSource::packTileFailed(const TileKey &key)
{
    if (!m_packPending.remove(key))
        return;
    queueForNetwork(key);
}

void XyzTileSource::queueForNetwork(const TileKey &key)
{
    const QString problem = m_template.problem();
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
    for (const TileKey &key : m_pack->cancelPending()) {
        if (m_packPending.remove(key))
            cancelled.append(key);
    }
    if (!cancelled.isEmpty())
        emit loadingCountChanged();
    return cancelled;
}

void XyzTileSource::startNext()
{
    while (!m_queue.isEmpty() && m_active.size() < m_maxConcurrent) {
        const TileKey key = m_queue.takeLast();
        if (m_cacheOnly) {
            start(key, Mode::CacheOnly); // never the network
        } else if (isReachable()) {
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
    request.setHeader(QNetworkRequest::UserAgentHeader, maptiles::sortieUserAgent());
    request.setAttribute(QNetworkRequest::CacheLoadControlAttribute,
                         mode == Mode::CacheOnly ? QNetworkRequest::AlwaysCache : QNetworkRequest::PreferCache);
    request.setAttribute(QNetworkRequest::RedirectPolicyAttribute, QNetworkRequest::NoLessSafeRedirectPolicy);
    request.setTransferTimeout(kTransferTimeoutMs);
    QNetworkReply *reply = m_network->get(request);
    maptiles::limitTileBody(reply);  // a server streaming without end is cut off (issue 36)
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

    if (const QString tooLarge = maptiles::tileBodyRefusal(reply); !tooLarge.isEmpty()) {
        m_probing = false;
        setReachable(true);  // the server answered; this tile is what is wrong
        emit tileFailed(key, tr("Tile %1 is %2.").arg(key.toString(), tooLarge));
    } else if (reply->error() == QNetworkReply::NoError) {
        if (!cacheOnly) {
            m_probing = false;
            setReachable(true);
        }
        decode(key, reply->readAll());
    } else if (m_cacheOnly) {
        emit tileFailed(key, tr("Tile %1 is neither in the offline pack nor in the cache (cache only: the network is not used).").arg(key.toString()));
    } else if (cacheOnly) {
        emit tileFailed(key, tr("Tile %1 is not in the cache and the tile server is unreachable.").arg(key.toString()));
    } else if (status.isValid() || isFile) {
        // The server answered: this tile is missing, the server is fine.
        m_probing = false;
        setReachable(true);
        emit tileFailed(key, isFile ? tr("No tile file %1.").arg(reply->url().toLocalFile())
                                    : tr("The tile server answered HTTP %1 for tile %2.").arg(status.toInt()).arg(key.toString()));
    } else {
        networkFailed(key, m_template.redacted(reply->errorString()));  // Qt quotes the URL, key and all
    }
    emit loadingCountChanged();
    startNext();
}

// Decoding a tile (a 256 px PNG: about a millisecond) is done on the thread pool, never on the GUI
// thread; Qt's image reader refuses a picture claiming more than its allocation limit.
void XyzTileSource::decode(const TileKey &key, QByteArray bytes)
{
    ++m_decoding;
    auto *watcher = new QFutureWatcher<QImage>(this);
    const quint64 generation = m_generation;
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, key, generation] {
        watcher->deleteLater();
        --m_decoding;
        const QImage image = watcher->result();
        if (generation == m_generation) {
            if (image.isNull())
                emit tileFailed(key, tr("Tile %1 is not an image.").arg(key.toString()));
            else
                emit tileReady(key, image);
        }
        emit loadingCountChanged();
    });
    watcher->setFuture(QtConcurrent::run([bytes = std::move(bytes)] {
        const QImage image = QImage::fromData(bytes);
        return image.isNull() ? image : image.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    }));
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
    ++m_generation;
    m_queue.clear();
    m_pack->cancelPending();
    m_packPending.clear();
    const auto replies = m_active.keys();
    m_active.clear();
    for (QNetworkReply *reply : replies)
        reply->abort(); // no longer in m_active: finished() ignores it
    emit loadingCountChanged();
    emit invalidated();
}

} // namespace sortie::ui
