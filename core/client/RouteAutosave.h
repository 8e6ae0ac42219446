#pragma once

#include "AutosaveDirectory.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <memory>

namespace sortie::client {

class RouteDocument;

// Keeps the route being edited on disk, so that a crash loses nothing. After each batch of edits
// (a single-shot timer restarted on every undo-stack change, so a drag or a burst of edits is one
// write) it writes the working route, the baseline (the route as last loaded or saved) and the
// route's server identity atomically to its slot's file (AutosaveRecord.h, AtomicFile.h). When
// the document becomes clean (loaded, saved, undone back to the saved state) the file is removed.
// The instance holds its slot's lock while it lives. On destruction a pending write is done; the
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
    // Writes now if the document has unsaved edits. False when that failed (see error()).
    bool writeNow();

signals:
    void written(const QString &path);
    void removed();
    void failed(const QString &message);

private:
    void edited();
    void takeBaseline();
    void remove();
    void fail(const QString &message);

    QPointer<RouteDocument> m_document;
    AutosaveDirectory m_directory;
    int m_slot = -1;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
    QByteArray m_baseline; // encoded once per baseline, not once per write
    QString m_server;
    QString m_user;
    QString m_error;
};

} // namespace sortie::client
