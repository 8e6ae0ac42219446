#pragma once

#include "AutosaveDirectory.h"

#include <QObject>
#include <QPointer>
#include <QThread>
#include <QTimer>

#include <memory>

namespace sortie::client {

class AutosaveWriter;
class RouteDocument;

// Keeps the route being edited on disk, so that a crash loses nothing. After each batch of edits
// (a single-shot timer restarted on every undo-stack change, so a drag or a burst of edits is one
// write) it writes the working route, the baseline (the route as last loaded or saved) and the
// route's server identity atomically to its slot's file (AutosaveRecord.h, AtomicFile.h). When
// the document becomes clean (loaded, saved, undone back to the saved state) the file is removed.
// The GUI thread only copies the route (a value type); an AutosaveWriter on a worker thread of
// this instance's own encodes and writes it, and removes the file, in the order they were asked
// (AutosaveWriter.h). Its signals reach this object's thread and are re-emitted from here.
// When undo goes back over an open (RouteDocument::open), the file is written with the baseline of
// the route undo brought back. The instance holds its slot's lock while it lives. On destruction a pending write is done; the
// file stays if the document still has unsaved edits (the next start offers them), else it goes.
class RouteAutosave : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QString filePath READ filePath CONSTANT)
    Q_PROPERTY(QString error READ error NOTIFY failed)

public:
    RouteAutosave(RouteDocument *document, const QString &directory, QObject *parent = nullptr);
    ~RouteAutosave() override;

    bool isActive() const { return m_lock != nullptr; }
    QString filePath() const;
    QString error() const { return m_error; }
    int slot() const { return m_slot; }

    // The server and user the route belongs to, recorded in the file (never a password).
    void setServer(const QString &address, const QString &user);
    void setDelay(int milliseconds) { m_timer.setInterval(milliseconds); }
    int delay() const { return m_timer.interval(); }
    // True while a batch of edits is under way: the write is queued delay() after the last edit.
    bool isBatching() const { return m_timer.isActive(); }
    // Queues a write of the route as it is now, if it has unsaved edits, and returns at once: the
    // GUI thread's whole share of a write (what the timer does after a batch of edits).
    void writeLater();
    // Writes now if the document has unsaved edits, and waits for the writer to finish it (and
    // whatever was queued before). False when that failed (see error()) or there was nothing to write.
    bool writeNow();
    // Waits until the writer has done everything queued so far.
    void waitForWriter();
    // The worker-side object that encodes and writes (it lives on its own thread); null when inactive.
    AutosaveWriter *writer() const { return m_writer; }

signals:
    void written(const QString &path);
    void removed();
    void failed(const QString &message);

private:
    void edited();
    void takeBaseline();
    bool queueWrite();
    void drainLater();
    QString drainAndWait();
    void fail(const QString &message);

    QPointer<RouteDocument> m_document;
    AutosaveDirectory m_directory;
    int m_slot = -1;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
    QThread m_thread;
    AutosaveWriter *m_writer = nullptr; // lives on m_thread; deleted once it has stopped
    QString m_server;
    QString m_user;
    QString m_error;
    bool m_baselineMoved = false; // the document's baseline changed since the writer was told
};

} // namespace sortie::client
