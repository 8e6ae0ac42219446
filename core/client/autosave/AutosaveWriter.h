#pragma once

#include "AutosaveRecord.h"

#include <QByteArray>
#include <QObject>
#include <QString>

#include <deque>
#include <mutex>
#include <optional>

namespace sortie::client {

// Encodes and writes one autosave slot's file on the thread it lives on (RouteAutosave moves it
// to a worker thread of its own), so the GUI thread only takes snapshots: the routes are value
// types, and copying a 10,000-waypoint route takes 0.1-1.5 ms (docs/performance.md), where
// encoding and writing it takes 60-80.
//
// Jobs run one at a time, in the order they were queued: a removal queued after a write runs
// after it, so a late write never brings back a file the document no longer needs. Only the
// newest snapshot matters: a write queued while another still waits replaces it, and a removal
// drops the writes waiting before it. queue*() may be called from any thread; drain() runs on
// the writer's thread (RouteAutosave invokes it there). Results come back as signals, emitted on
// the writer's thread.
class AutosaveWriter : public QObject
{
    Q_OBJECT

public:
    explicit AutosaveWriter(QString path);

    QString path() const { return m_path; }

    // Write `working` with `header`'s identity and the current baseline, which `baseline` replaces
    // first when given (undo went back to a route opened before). True when drain() must be
    // invoked (the queue was empty: no drain is on its way).
    [[nodiscard]] bool queueWrite(AutosaveRecord header, mission::Route working,
                                  std::optional<mission::Route> baseline = std::nullopt);
    // Remove the file; when `baseline` is given, it becomes the baseline of the following writes
    // (encoded here, on the writer's thread, once per baseline).
    [[nodiscard]] bool queueRemove(std::optional<mission::Route> baseline = std::nullopt);
    // Jobs queued and not started yet.
    int queued() const;

    // Runs the queued jobs. Returns the error of the last job run, by this call or an earlier one
    // ("" when it succeeded): what a caller that waits for the writer needs to know.
    QString drain();

signals:
    void written(const QString &path);
    void removed();
    void failed(const QString &message);

private:
    struct Job
    {
        enum Kind { Write, Remove } kind = Write;
        AutosaveRecord header; // Write: identity and time; header.working is the snapshot
        std::optional<mission::Route> baseline; // the new baseline, if it moved
    };
    QString run(Job &job);

    const QString m_path;
    mutable std::mutex m_mutex;
    std::deque<Job> m_jobs; // guarded by m_mutex
    QByteArray m_baseline;  // encoded; touched only by drain()
    QString m_lastError;    // touched only by drain()
};

} // namespace sortie::client
