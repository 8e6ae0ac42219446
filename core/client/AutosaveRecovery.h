#pragma once

#include "AutosaveDirectory.h"
#include "AutosaveRecord.h"

#include <QDateTime>
#include <QObject>
#include <QPointer>
#include <QStringList>

#include <memory>
#include <optional>

namespace sortie::client {

class RouteDocument;

// At start: finds edits autosaved by an instance that is no longer running (its slot's lock is
// free or stale; a live instance's autosave is never offered), shows what they change since the
// last save, and restores or discards them. An unreadable file is moved aside under a new name
// and named in `message`, never deleted. Restore loads the baseline into the document and applies
// the autosaved route as one undoable step, so the document has unsaved edits and saving goes to
// the same server route. Discard keeps the file as the one discarded backup.
class AutosaveRecovery : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool available READ isAvailable NOTIFY changed)
    Q_PROPERTY(QString fileName READ fileName NOTIFY changed)
    Q_PROPERTY(QString routeName READ routeName NOTIFY changed)
    Q_PROPERTY(QString origin READ origin NOTIFY changed)
    Q_PROPERTY(QDateTime savedAt READ savedAt NOTIFY changed)
    Q_PROPERTY(QStringList changes READ changes NOTIFY changed)
    Q_PROPERTY(QString summary READ summary NOTIFY changed)
    Q_PROPERTY(QString message READ message NOTIFY messageChanged)

public:
    AutosaveRecovery(RouteDocument *document, const QString &directory, QObject *parent = nullptr);
    ~AutosaveRecovery() override;

    // Looks for the next autosave to offer (done by the constructor too).
    void scan();

    bool isAvailable() const { return m_record.has_value(); }
    const AutosaveRecord *record() const { return m_record ? &*m_record : nullptr; }
    QString fileName() const { return m_slot > 0 ? m_directory.filePath(m_slot) : QString(); }
    QString routeName() const;
    // "route 42, version 3, on 127.0.0.1:3334 as admin"; empty for a route from a file.
    QString origin() const;
    QDateTime savedAt() const { return m_record ? m_record->savedAt : QDateTime(); }
    QStringList changes() const { return m_changes; }
    QString summary() const { return m_summary; }
    QString message() const { return m_message; }

    Q_INVOKABLE bool restore();
    Q_INVOKABLE void discard();

signals:
    void changed();
    void messageChanged();
    void restored();

private:
    void release();
    void addMessage(const QString &text);

    QPointer<RouteDocument> m_document;
    AutosaveDirectory m_directory;
    int m_slot = -1;
    std::unique_ptr<QLockFile> m_lock;
    std::optional<AutosaveRecord> m_record;
    QStringList m_changes;
    QString m_summary;
    QString m_message;
};

} // namespace sortie::client
