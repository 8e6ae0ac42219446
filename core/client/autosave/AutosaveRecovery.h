#pragma once

#include "AutosaveDirectory.h"
#include "AutosaveRecord.h"

#include <QAbstractListModel>
#include <QDateTime>
#include <QPointer>
#include <QStringList>

#include <memory>
#include <vector>

namespace sortie::client {

class RouteDocument;

// At start: finds every autosave left by an instance that is no longer running (its slot's lock
// is free or stale; a live instance's autosave is never offered) and offers them together, one
// row each, newest first, with what each changes since its last save. The operator restores one
// or discards any; the current row is the one the single-value properties describe and restore()
// and discard() act on. An unreadable file is moved aside under a new name and named in
// `message`, never deleted.
//
// Restore loads the baseline into the document and applies the autosaved route as one undoable
// step, so the document has unsaved edits and saving goes to the same server route. Because of
// that, edits of a server route are restored only in a session signed in to the same server as
// the same user (setSession); otherwise `restoreBlocker` says what to do, and the autosave stays
// offered. Nor do they replace unsaved edits of the route open now. After a restore the other
// rows are kept on disk for the next start. Discard keeps the file as the one discarded backup.
// postpone() hides the offer ("Later", e.g. to sign in first) until the session changes.
class AutosaveRecovery : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(bool available READ isAvailable NOTIFY changed)
    Q_PROPERTY(int count READ count NOTIFY changed)
    Q_PROPERTY(int currentRow READ currentRow WRITE setCurrentRow NOTIFY changed)
    Q_PROPERTY(QString fileName READ fileName NOTIFY changed)
    Q_PROPERTY(QString routeName READ routeName NOTIFY changed)
    Q_PROPERTY(QString origin READ origin NOTIFY changed)
    Q_PROPERTY(QDateTime savedAt READ savedAt NOTIFY changed)
    Q_PROPERTY(QStringList changes READ changes NOTIFY changed)
    Q_PROPERTY(QString summary READ summary NOTIFY changed)
    Q_PROPERTY(QString restoreBlocker READ restoreBlocker NOTIFY changed)
    Q_PROPERTY(QString message READ message NOTIFY messageChanged)

public:
    enum Roles {
        RouteNameRole = Qt::UserRole + 1,
        OriginRole,        // "route 42, version 3, on 127.0.0.1:3334 as admin"; empty for a route from a file
        SavedAtRole,
        SummaryRole,       // "3 changes: WP 2 moved 33 m, ..."
        FileNameRole,
        RestoreBlockerRole // why it cannot be restored now and what to do; empty when it can
    };
    Q_ENUM(Roles)

    AutosaveRecovery(RouteDocument *document, const QString &directory, QObject *parent = nullptr);
    ~AutosaveRecovery() override;

    // Looks for the autosaves to offer (done by the constructor too).
    void scan();
    // The session the client is signed in to; empty when it is not.
    void setSession(const QString &server, const QString &user);

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QHash<int, QByteArray> roleNames() const override;

    // Something is offered and the operator has not put it off.
    bool isAvailable() const { return !m_offers.empty() && !m_postponed; }
    int count() const { return int(m_offers.size()); }
    int currentRow() const { return m_current; }
    void setCurrentRow(int row);
    const AutosaveRecord *record() const { return current() ? &current()->record : nullptr; }
    QString fileName() const;
    QString routeName() const;
    QString origin() const;
    QDateTime savedAt() const { return current() ? current()->record.savedAt : QDateTime(); }
    QStringList changes() const { return current() ? current()->changes : QStringList(); }
    QString summary() const { return current() ? current()->summary : QString(); }
    QString restoreBlocker() const { return current() ? blockerOf(*current()) : QString(); }
    QString message() const { return m_message; }

    // Act on the current row.
    Q_INVOKABLE bool restore();
    Q_INVOKABLE void discard();
    Q_INVOKABLE void postpone();
    // The operator read `message` (a file kept aside, a move that failed): it is cleared.
    Q_INVOKABLE void acknowledgeMessage();

signals:
    void changed();
    void messageChanged();
    void restored();

private:
    struct Offer
    {
        int slot = -1;
        std::unique_ptr<QLockFile> lock;
        AutosaveRecord record;
        QStringList changes;
        QString summary;
    };
    const Offer *current() const { return m_current >= 0 && m_current < count() ? &m_offers[size_t(m_current)] : nullptr; }
    QString routeNameOf(const Offer &offer) const;
    QString originOf(const Offer &offer) const;
    QString blockerOf(const Offer &offer) const;
    void setOffers(std::vector<Offer> offers);
    void moveAside(int row);
    void addMessage(const QString &text);

    QPointer<RouteDocument> m_document;
    AutosaveDirectory m_directory;
    std::vector<Offer> m_offers;
    int m_current = -1;
    bool m_postponed = false;
    QString m_server;
    QString m_user;
    QString m_message;
};

} // namespace sortie::client
