#include "TilePrefetch.h"

#include "MapTilesLog.h"
#include "TileResponse.h"

#include <QCoreApplication>
#include <QNetworkAccessManager>
#include <QNetworkReply>

#include <algorithm>
#include <cmath>

namespace sortie::maptiles {

Q_LOGGING_CATEGORY(lcMapTiles, "sortie.maptiles")

namespace {
constexpr auto kAbortedProperty = "sortiePrefetchAborted";
} // namespace

QString sortieUserAgent()
{
    return QStringLiteral("Sortie/%1 (drone ground station)").arg(QStringLiteral(SORTIE_VERSION));  // i18n: not text (a protocol string)
}

TilePrefetch::TilePrefetch(QNetworkAccessManager *network, PrefetchPlan plan, PrefetchLimits limits, QObject *parent)
    : QObject(parent)
    , m_network(network)
    , m_plan(std::move(plan))
    , m_limits(limits)
{
    m_limits.maximumConcurrent = std::max(1, m_limits.maximumConcurrent);
    m_limits.maximumAttempts = std::max(1, m_limits.maximumAttempts);
    m_flushTimer.setSingleShot(true);
    m_wakeTimer.setSingleShot(true);
    connect(&m_flushTimer, &QTimer::timeout, this, &TilePrefetch::flush);
    connect(&m_wakeTimer, &QTimer::timeout, this, &TilePrefetch::pump);
}

TilePrefetch::~TilePrefetch()
{
    if (m_state == State::Running || m_state == State::Paused)
        stop();
}

bool TilePrefetch::start()
{
    if (m_state != State::Idle)
        return m_state == State::Running;
    const auto refuse = [this](const QString &why) {
        m_problem = why;
        qCWarning(lcMapTiles) << "prefetch refused:" << why;
        setState(State::Failed);
        return false;
    };
    if (!m_plan.server.isUsable())
        return refuse(m_plan.server.problem());
    if (m_plan.area.isEmpty())
        return refuse(m_plan.area.problem().isEmpty() ? tr("No area is chosen.") : m_plan.area.problem());
    if (m_plan.minZoom < 0 || m_plan.maxZoom > TileArea::kMaximumZoom || m_plan.minZoom > m_plan.maxZoom)
        return refuse(tr("The zoom range %1 to %2 is not within 0 to %3.").arg(m_plan.minZoom).arg(m_plan.maxZoom).arg(TileArea::kMaximumZoom));
    m_total = m_plan.area.tileCount(m_plan.minZoom, m_plan.maxZoom);
    if (m_total > m_limits.maximumTiles)
        return refuse(tr("The area needs %1 tiles, more than the limit of %2: choose a smaller area or fewer zoom levels.")
                          .arg(m_total).arg(m_limits.maximumTiles));
    QString error;
    if (!m_file.open(m_plan.file, MbTilesFile::Mode::ReadWrite, &error))
        return refuse(error);

    MbTilesMetadata meta = m_file.metadata();
    for (const QString &problem : std::as_const(meta.problems))
        qCWarning(lcMapTiles) << m_plan.file << "metadata:" << problem;
    const QString host = m_plan.server.host();
    if (!m_plan.name.isEmpty() || meta.name.isEmpty())
        meta.name = m_plan.name.isEmpty() ? host : m_plan.name;
    if (!m_plan.attribution.isEmpty())
        meta.attribution = m_plan.attribution;
    meta.description = tr("Tiles from %1, taken offline by %2").arg(host, sortieUserAgent());
    meta.minZoom = std::min(meta.minZoom.value_or(m_plan.minZoom), m_plan.minZoom);
    meta.maxZoom = std::max(meta.maxZoom.value_or(m_plan.maxZoom), m_plan.maxZoom);
    const GeoBounds area = m_plan.area.bounds();
    if (meta.bounds && meta.bounds->west < meta.bounds->east && area.west < area.east)
        meta.bounds = GeoBounds{std::min(meta.bounds->south, area.south), std::min(meta.bounds->west, area.west),
                                std::max(meta.bounds->north, area.north), std::max(meta.bounds->east, area.east)};
    else
        meta.bounds = area;
    m_format = meta.format;
    m_formatWritten = !meta.format.isEmpty();
    if (!m_file.writeMetadata(meta, &error))
        return refuse(error);
    m_stored = m_file.storedTiles(m_plan.minZoom, m_plan.maxZoom, &error);
    if (!error.isEmpty())
        return refuse(error);

    m_zoom = m_plan.minZoom;
    m_spans = m_plan.area.spans(m_zoom);
    qCInfo(lcMapTiles) << "prefetch of" << m_total << "tiles, zoom" << m_plan.minZoom << "to" << m_plan.maxZoom << "from" << host
                       << "into" << m_plan.file << "(" << m_stored.size() << "tiles of those zooms already there)";
    setState(State::Running);
    pump();
    return true;
}

void TilePrefetch::pause()
{
    if (m_state != State::Running)
        return;
    setState(State::Paused);
    const auto replies = m_inFlight.keys();
    for (QNetworkReply *reply : replies) {
        reply->setProperty(kAbortedProperty, true);
        reply->abort(); // finished() puts the tile back at the head of the queue
    }
    m_wakeTimer.stop();
    flush();
    emit progressChanged();
}

void TilePrefetch::resume()
{
    if (m_state != State::Paused)
        return;
    setState(State::Running);
    pump();
}

void TilePrefetch::stop()
{
    if (m_state != State::Running && m_state != State::Paused)
        return;
    pause();
    m_file.close();
    setState(State::Stopped);
}

bool TilePrefetch::nextPlanned(TileId *tile)
{
    while (true) {
        if (m_span < m_spans.size()) {
            const TileSpan &span = m_spans.at(m_span);
            m_column = std::max(m_column, span.firstColumn);
            if (m_column <= span.lastColumn) {
                *tile = {m_zoom, m_column++, span.row};
                return true;
            }
            ++m_span;
            m_column = 0;
            continue;
        }
        if (m_zoom >= m_plan.maxZoom)
            return false;
        m_spans = m_plan.area.spans(++m_zoom);
        m_span = 0;
        m_column = 0;
    }
}

void TilePrefetch::pump()
{
    if (m_state != State::Running)
        return;
    while (m_inFlight.size() < m_limits.maximumConcurrent && m_holdUntil.hasExpired()) {
        const auto due = std::find_if(m_retryQueue.begin(), m_retryQueue.end(), [](const Pending &p) { return p.due.hasExpired(); });
        if (due != m_retryQueue.end()) {
            const Pending pending = *due;
            m_retryQueue.erase(due);
            request(pending);
            continue;
        }
        TileId tile;
        bool found = false;
        while (nextPlanned(&tile)) {
            if (!m_stored.contains(tile.packed())) {
                found = true;
                break;
            }
            ++m_skipped; // resuming: already in the file
        }
        if (!found)
            break;
        request({tile, 1, {}});
    }
    emit progressChanged();
    finishIfDone();
    scheduleWake();
}

void TilePrefetch::request(const Pending &pending)
{
    QNetworkRequest request(m_plan.server.url(pending.tile));
    request.setHeader(QNetworkRequest::UserAgentHeader, sortieUserAgent());
    request.setTransferTimeout(m_limits.timeoutMs);
    request.setAttribute(QNetworkRequest::RedirectPolicyAttribute, QNetworkRequest::NoLessSafeRedirectPolicy);
    request.setAttribute(QNetworkRequest::CacheLoadControlAttribute, QNetworkRequest::AlwaysNetwork);
    request.setAttribute(QNetworkRequest::CacheSaveControlAttribute, false);
    QNetworkReply *reply = m_network->get(request);
    limitTileBody(reply);
    m_inFlight.insert(reply, pending);
    connect(reply, &QNetworkReply::finished, this, [this, reply] { replyFinished(reply); });
}

void TilePrefetch::replyFinished(QNetworkReply *reply)
{
    reply->deleteLater();
    const auto it = m_inFlight.find(reply);
    if (it == m_inFlight.end())
        return;
    const Pending pending = it.value();
    m_inFlight.erase(it);
    if (reply->property(kAbortedProperty).toBool()) {
        m_retryQueue.prepend({pending.tile, pending.attempt, QDeadlineTimer(0)});
        return;
    }
    const TileId &tile = pending.tile;
    const QVariant status = reply->attribute(QNetworkRequest::HttpStatusCodeAttribute);
    if (const QString tooLarge = tileBodyRefusal(reply); !tooLarge.isEmpty()) {
        fail(tile, tooLarge);  // the same server would send the same: not retried
    } else if (reply->error() == QNetworkReply::NoError) {
        const QByteArray bytes = reply->readAll();
        const TileFormat format = sniffTileFormat(bytes);
        if (format == TileFormat::Unknown) {
            fail(tile, tr("not an image (%1, %2 bytes)")
                           .arg(reply->header(QNetworkRequest::ContentTypeHeader).toString().section(QLatin1Char(';'), 0, 0).trimmed(),
                                QString::number(bytes.size())));
        } else {
            if (m_format.isEmpty())
                m_format = formatName(format);
            m_batch.append({tile, bytes});
            ++m_downloaded;
            m_downloadedBytes += bytes.size();
            if (m_batch.size() >= m_limits.batchSize)
                flush();
            else if (!m_flushTimer.isActive())
                m_flushTimer.start(m_limits.flushIntervalMs);
        }
    } else if (status.isValid()) {
        const int code = status.toInt();
        const QString why = QStringLiteral("HTTP %1 %2").arg(code).arg(reply->attribute(QNetworkRequest::HttpReasonPhraseAttribute).toString()).trimmed();  // i18n: not text (a protocol string)
        if (isRetryableStatus(code))
            retryLater(pending, why, parseRetryAfter(reply->rawHeader("Retry-After"), QDateTime::currentDateTimeUtc()));
        else
            fail(tile, why);
    } else {
        // No answer: a timeout, a refused or dropped connection. The server may be back soon.
        const bool timedOut = reply->error() == QNetworkReply::OperationCanceledError;
        retryLater(pending, timedOut ? tr("no answer within %1 s").arg(m_limits.timeoutMs / 1000.0) : m_plan.server.redacted(reply->errorString()), std::nullopt);
    }
    pump();
}

void TilePrefetch::retryLater(const Pending &pending, const QString &why, std::optional<double> retryAfter)
{
    if (pending.attempt >= m_limits.maximumAttempts) {
        fail(pending.tile, tr("%1 (after %2 attempts)").arg(why).arg(pending.attempt));
        return;
    }
    // The server's Retry-After is honoured as given (up to an hour); our own back-off doubles to a cap.
    const double delayMs = retryAfter ? std::min(*retryAfter * 1000.0, 3600.0 * 1000.0)
                                      : std::min<double>(m_limits.firstRetryDelayMs * std::pow(2.0, pending.attempt - 1),
                                                         m_limits.longestRetryDelayMs);
    if (retryAfter) {
        // The server asked everyone to wait: hold every request, not just this tile's.
        const QDeadlineTimer hold{qint64(delayMs)};
        if (hold.deadline() > m_holdUntil.deadline() || m_holdUntil.hasExpired())
            m_holdUntil = hold;
    }
    ++m_retries;
    qCInfo(lcMapTiles) << "tile" << pending.tile.toString() << why << "- attempt" << pending.attempt + 1 << "in" << delayMs << "ms";
    m_retryQueue.append({pending.tile, pending.attempt + 1, QDeadlineTimer(qint64(delayMs))});
}

void TilePrefetch::fail(const TileId &tile, const QString &why)
{
    m_failedTiles.append(tile.toString() + QStringLiteral(": ") + why);
    qCWarning(lcMapTiles) << "tile" << tile.toString() << "not stored:" << why;
}

void TilePrefetch::flush()
{
    m_flushTimer.stop();
    if (m_batch.isEmpty() || !m_file.isOpen())
        return;
    QString error;
    if (!m_file.writeTiles(m_batch, &error)) {
        m_problem = error;
        qCWarning(lcMapTiles) << "prefetch stopped:" << error;
        m_downloaded -= m_batch.size();
        m_batch.clear();
        const auto replies = m_inFlight.keys();
        for (QNetworkReply *reply : replies) {
            reply->setProperty(kAbortedProperty, true);
            reply->abort();
        }
        m_file.close();
        setState(State::Failed);
        return;
    }
    for (const MbTilesFile::Tile &tile : std::as_const(m_batch))
        m_stored.insert(tile.id.packed());
    m_batch.clear();
    if (!m_formatWritten && !m_format.isEmpty()) {
        // The first tiles say what the server sends: MBTiles readers want it in the metadata.
        MbTilesMetadata meta = m_file.metadata();
        meta.format = m_format;
        m_formatWritten = m_file.writeMetadata(meta, &error);
    }
}

void TilePrefetch::setState(State state)
{
    if (state == m_state)
        return;
    m_state = state;
    emit stateChanged();
}

void TilePrefetch::finishIfDone()
{
    if (m_state != State::Running || !m_inFlight.isEmpty() || !m_retryQueue.isEmpty())
        return;
    if (m_zoom < m_plan.maxZoom || m_span < m_spans.size())
        return; // not yet at the end of the plan
    flush();
    m_file.close();
    qCInfo(lcMapTiles) << "prefetch finished:" << m_downloaded << "downloaded," << m_skipped << "already there," << failed() << "not stored";
    setState(State::Finished);
    emit progressChanged();
    emit finished();
}

void TilePrefetch::scheduleWake()
{
    if (m_state != State::Running || m_inFlight.size() >= m_limits.maximumConcurrent || m_retryQueue.isEmpty())
        return;
    qint64 wait = std::numeric_limits<qint64>::max();
    for (const Pending &pending : std::as_const(m_retryQueue))
        wait = std::min(wait, pending.due.remainingTime());
    wait = std::max({wait, m_holdUntil.remainingTime(), qint64(1)});
    m_wakeTimer.start(int(std::min<qint64>(wait, 600000)));
}

} // namespace sortie::maptiles
