#pragma once

#include "MbTilesFile.h"
#include "TileArea.h"
#include "TileUrlTemplate.h"

#include <QDeadlineTimer>
#include <QHash>
#include <QObject>
#include <QStringList>
#include <QTimer>

class QNetworkAccessManager;
class QNetworkReply;

namespace sortie::maptiles {

// What to take offline: the server, the area, the zooms, the file, and what the provider asks of
// those who download from it (its attribution goes into the file's metadata).
struct PrefetchPlan
{
    TileUrlTemplate server;
    TileArea area;
    int minZoom = 0;
    int maxZoom = 0;
    QString file;
    QString name;        // the file's `name`; empty: the server's host
    QString attribution; // kept in the file's metadata, shown by the map
};

// How hard to press the server.
struct PrefetchLimits
{
    int maximumConcurrent = 2;         // requests in flight at once
    qint64 maximumTiles = 100000;      // a plan needing more is refused before anything is fetched
    int maximumAttempts = 4;           // per tile, the first included
    int timeoutMs = 15000;             // a transfer that stalls this long is retried
    int firstRetryDelayMs = 1000;      // doubled per attempt unless the server says (Retry-After)
    int longestRetryDelayMs = 120000;
    int batchSize = 32;                // tiles per transaction
    int flushIntervalMs = 1000;        // a smaller batch is written after this long
};

// The User-Agent every tile request of Sortie carries: the program and its version.
QString sortieUserAgent();

// Downloads a plan's tiles into an MBTiles file. Tiles already in the file are skipped (so a job
// started again after a restart resumes); good tiles are written in transactions; a 404 or bytes
// that are not an image are counted and named, never stored; 429, 5xx, timeouts and dropped
// connections are retried with back-off (Retry-After honoured: a 429 or 503 that names a wait
// holds every request until then). Pause stops requesting and writes what arrived.
class TilePrefetch : public QObject
{
    Q_OBJECT

public:
    enum class State { Idle, Running, Paused, Finished, Failed, Stopped };
    Q_ENUM(State)

    TilePrefetch(QNetworkAccessManager *network, PrefetchPlan plan, PrefetchLimits limits = {}, QObject *parent = nullptr);
    ~TilePrefetch() override;

    // Opens (or creates) the file, counts what is there and starts; false with problem() when the
    // plan cannot run (bad template, area or zooms, too many tiles, unwritable file).
    bool start();
    void pause();
    void resume();
    // Ends the job for good; what arrived is written.
    void stop();

    State state() const { return m_state; }
    QString problem() const { return m_problem; }
    qint64 total() const { return m_total; }            // tiles in the plan
    qint64 skipped() const { return m_skipped; }        // already in the file
    qint64 downloaded() const { return m_downloaded; }  // fetched in this run (written, or in the batch being written)
    qint64 failed() const { return m_failedTiles.size(); }
    qint64 done() const { return m_skipped + m_downloaded + failed(); }
    qint64 retries() const { return m_retries; }
    qint64 downloadedBytes() const { return m_downloadedBytes; }
    int inFlight() const { return int(m_inFlight.size()); }
    // Whether a timer will ask for more (a back-off or a wait for room); never while paused.
    bool wakeScheduled() const { return m_wakeTimer.isActive(); }
    // Each tile that could not be stored and why ("14/8800/5371: HTTP 404").
    QStringList failures() const { return m_failedTiles; }

signals:
    void progressChanged();
    void stateChanged();
    void finished();

private:
    struct Pending
    {
        TileId tile;
        int attempt = 1;
        QDeadlineTimer due;
    };

    bool nextPlanned(TileId *tile);
    void pump();
    void request(const Pending &pending);
    void replyFinished(QNetworkReply *reply);
    void retryLater(const Pending &pending, const QString &why, std::optional<double> retryAfter);
    void fail(const TileId &tile, const QString &why);
    void flush();
    void setState(State state);
    void finishIfDone();
    void scheduleWake();

    QNetworkAccessManager *m_network;
    PrefetchPlan m_plan;
    PrefetchLimits m_limits;
    MbTilesFile m_file;
    State m_state = State::Idle;
    QString m_problem;
    QSet<quint64> m_stored;
    // The plan's cursor: zoom, its spans, the span and column reached.
    int m_zoom = 0;
    QList<TileSpan> m_spans;
    qsizetype m_span = 0;
    int m_column = 0;
    QList<Pending> m_retryQueue;
    QHash<QNetworkReply *, Pending> m_inFlight;
    QDeadlineTimer m_holdUntil;
    QList<MbTilesFile::Tile> m_batch;
    QTimer m_flushTimer;
    QTimer m_wakeTimer;
    QString m_format;
    bool m_formatWritten = false;
    qint64 m_total = 0;
    qint64 m_skipped = 0;
    qint64 m_downloaded = 0;
    qint64 m_retries = 0;
    qint64 m_downloadedBytes = 0;
    QStringList m_failedTiles;
};

} // namespace sortie::maptiles
