#pragma once

#include "RecordingChunk.h"

#include <QHash>
#include <QMutex>
#include <QObject>
#include <QSqlDatabase>

#include <atomic>
#include <deque>
#include <memory>

class QLockFile;

namespace sortie::flightlog {

// How big a session's log may grow, and how much the log folder may hold; the operator sets both.
struct RecordingLimits
{
    qint64 maxFileBytes = 256ll << 20;   // a log reaching it continues in a new part (<name>-2.sortielog, ...)
    qint64 maxFolderBytes = 4ll << 30;   // the oldest logs in the folder are deleted beyond it; 0: never
};

// Writes recording chunks into a SQLite flight log (docs/flightlog.md). Lives on the recorder's
// writer thread: the database connection is created, used and closed there. Each chunk is one
// transaction, committed with the WAL synced, so a killed process loses only the chunk in flight.
// A chunk whose commit fails (disk full, an I/O error) is rolled back whole, vehicle rows it made
// included, and kept: the next write commits it first, in order, then the new one (up to
// kMaxUnwrittenValues values are kept; beyond that the oldest chunks' telemetry is dropped, and
// counted). While a log is being written, a lock file beside it (<log>.lock) tells pruneFolder()
// of another process to leave it alone.
class FlightLogWriter : public QObject
{
    Q_OBJECT

public:
    struct Stats
    {
        quint64 values = 0;  // telemetry values written
        quint64 blocks = 0;
        quint64 blockBytes = 0; // encoded telemetry bytes
        qint64 cpuNs = 0;    // CPU time this thread spent encoding and writing
        int parts = 0;       // files written (1 + rotations)
    };

    FlightLogWriter(QString path, RecordingLimits limits, QObject *parent = nullptr);
    ~FlightLogWriter() override;

    bool open(QString *error);
    void write(const RecordingChunk &chunk);
    void close();

    QString currentPath() const;
    Stats stats() const;
    // Chunks whose commit failed, waiting to be written again.
    int unwrittenChunks() const { return int(m_unwritten.size()); }
    static constexpr quint64 kMaxUnwrittenValues = 2'000'000; // about 32 MB of samples

    // New limits, from any thread: every later write checks against them.
    void setLimits(RecordingLimits limits);
    // On the writer's thread: continues in a new part if the log is over its limit now, and prunes
    // the folder to its limit (what a change of the limits asks for at once).
    void enforceLimits();
    RecordingLimits limits() const { return {m_maxFileBytes.load(), m_maxFolderBytes.load()}; }

    // Deletes the oldest *.sortielog files in `folder` (never `keep`, never one a live writer holds
    // the lock of, in this process or another) until the folder holds at most maxBytes of them;
    // returns the files removed.
    static QStringList pruneFolder(const QString &folder, qint64 maxBytes, const QString &keep);
    // What the *.sortielog files in `folder` (with their journals) take on disk, and how many there are.
    static qint64 folderBytes(const QString &folder, int *logs = nullptr);

signals:
    void errorOccurred(const QString &message);
    void rotated(const QString &path);

private:
    bool openPart(const QString &path, QString *error);
    bool writeChunk(const RecordingChunk &chunk, QString *error);
    // writeChunk(), rolled back whole when it fails.
    bool commit(const RecordingChunk &chunk, QString *error);
    void keepUnwritten(const RecordingChunk &chunk);
    qint64 vehicleRow(const QString &key);
    qint64 sizeOnDisk();
    void rotate();

    QString m_basePath;
    QString m_path;
    QString m_connection;
    std::atomic<qint64> m_maxFileBytes, m_maxFolderBytes; // set from the recorder's thread
    QSqlDatabase m_db;
    QHash<QString, qint64> m_vehicleRows;
    QHash<QString, RecordedVehicle> m_vehicles;          // to repeat in a new part
    QHash<QString, RecordedMission> m_lastMissions;      // likewise
    std::deque<RecordingChunk> m_unwritten;              // failed commits, oldest first
    quint64 m_unwrittenValues = 0;
    quint64 m_droppedValues = 0;
    std::unique_ptr<QLockFile> m_lock;                   // the part being written
    bool m_failed = false;
    std::atomic<quint64> m_values{0}, m_blocks{0}, m_blockBytes{0};
    std::atomic<qint64> m_cpuNs{0};
    std::atomic<int> m_parts{0};
    mutable QMutex m_pathMutex; // m_path is read from the recorder's thread
};

} // namespace sortie::flightlog
