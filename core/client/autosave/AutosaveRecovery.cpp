#include "AutosaveRecovery.h"

#include "RouteDiff.h"
#include "RouteDocument.h"

#include <QFile>
#include <QFileInfo>
#include <QLoggingCategory>

#include <algorithm>

Q_DECLARE_LOGGING_CATEGORY(lcAutosave)

namespace sortie::client {

using namespace sortie::mission;

AutosaveRecovery::AutosaveRecovery(RouteDocument *document, const QString &directory, QObject *parent)
    : QAbstractListModel(parent)
    , m_document(document)
    , m_directory(directory)
{
    if (document) {
        // Whether a restore would replace unsaved edits decides what may be restored.
        connect(document, &RouteDocument::modifiedChanged, this, [this] {
            if (!m_offers.empty())
                emit dataChanged(index(0), index(count() - 1), {RestoreBlockerRole});
            emit changed();
        });
    }
    scan();
}

AutosaveRecovery::~AutosaveRecovery() = default;

void AutosaveRecovery::scan()
{
    setOffers({}); // releases the locks held so far
    std::vector<Offer> offers;
    for (int slot : m_directory.slotsWithFiles()) {
        auto lock = m_directory.tryLock(slot);
        if (!lock)
            continue; // a running instance's
        const QString path = m_directory.filePath(slot);
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) {
            if (QFileInfo::exists(path))
                addMessage(tr("The autosaved edits in %1 cannot be read: %2").arg(path, file.errorString()));
            continue;
        }
        auto decoded = decodeAutosave(file.readAll());
        file.close();
        if (!decoded) {
            const QString aside = m_directory.corruptPath(slot);
            const bool moved = QFile::rename(path, aside);
            const QString error = decoded.error().withFile(QFileInfo(path).fileName()).toString();
            addMessage(moved ? tr("The autosaved edits in %1 cannot be read (%2). The file was kept as %3.").arg(path, error, aside)
                             : tr("The autosaved edits in %1 cannot be read (%2).").arg(path, error));
            continue;
        }
        Offer offer;
        offer.slot = slot;
        offer.lock = std::move(lock);
        offer.record = std::move(decoded).value();
        const RouteDiff diff = RouteDiff::compare(offer.record.baseline, offer.record.working);
        offer.changes = diff.texts();
        offer.summary = diff.summary();
        qCInfo(lcAutosave).noquote() << "offering" << path << ":" << offer.summary;
        offers.push_back(std::move(offer));
    }
    std::reverse(offers.begin(), offers.end()); // newest first
    setOffers(std::move(offers));
}

void AutosaveRecovery::setSession(const QString &server, const QString &user)
{
    if (server == m_server && user == m_user)
        return;
    m_server = server;
    m_user = user;
    m_postponed = false; // what was put off to sign in first is offered again
    if (!m_offers.empty())
        emit dataChanged(index(0), index(count() - 1), {RestoreBlockerRole});
    emit changed();
}

int AutosaveRecovery::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QVariant AutosaveRecovery::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Offer &offer = m_offers[size_t(index.row())];
    switch (role) {
    case Qt::DisplayRole:
    case RouteNameRole:
        return routeNameOf(offer);
    case OriginRole:
        return originOf(offer);
    case SavedAtRole:
        return offer.record.savedAt;
    case SummaryRole:
        return offer.summary;
    case FileNameRole:
        return m_directory.filePath(offer.slot);
    case RestoreBlockerRole:
        return blockerOf(offer);
    default:
        return {};
    }
}

QHash<int, QByteArray> AutosaveRecovery::roleNames() const
{
    return {{RouteNameRole, "routeName"}, {OriginRole, "origin"},     {SavedAtRole, "savedAt"},
            {SummaryRole, "summary"},     {FileNameRole, "fileName"}, {RestoreBlockerRole, "restoreBlocker"}};
}

void AutosaveRecovery::setCurrentRow(int row)
{
    row = m_offers.empty() ? -1 : std::clamp(row, 0, count() - 1);
    if (row == m_current)
        return;
    m_current = row;
    emit changed();
}

QString AutosaveRecovery::fileName() const
{
    return current() ? m_directory.filePath(current()->slot) : QString();
}

QString AutosaveRecovery::routeName() const
{
    return current() ? routeNameOf(*current()) : QString();
}

QString AutosaveRecovery::origin() const
{
    return current() ? originOf(*current()) : QString();
}

QString AutosaveRecovery::routeNameOf(const Offer &offer) const
{
    const QString name = offer.record.working.settings.name;
    return name.isEmpty() ? tr("Untitled route") : name;
}

QString AutosaveRecovery::originOf(const Offer &offer) const
{
    const AutosaveRecord &r = offer.record;
    if (r.routeId < 0)
        return {};
    QString text = tr("route %1, version %2").arg(r.routeId).arg(r.routeVersion);
    if (!r.server.isEmpty())
        text += tr(", on %1").arg(r.server);
    if (!r.user.isEmpty())
        text += tr(" as %1").arg(r.user);
    return text;
}

QString AutosaveRecovery::blockerOf(const Offer &offer) const
{
    if (m_document && m_document->isModified())
        return tr("The route open now has unsaved edits, and restoring would replace it: save or undo them first.");
    const AutosaveRecord &r = offer.record;
    // Only edits of a server route are bound to a session: saving them goes to that route.
    if (r.routeId < 0 || r.server.isEmpty())
        return {};
    const QString owner = r.user.isEmpty() ? r.server : tr("%1 as %2").arg(r.server, r.user);
    if (m_server.isEmpty())
        return tr("These edits belong to route %1 on %2, and saving them updates that route. Sign in to %2 to restore "
                  "them: choose Later, sign in, and they are offered again.").arg(QString::number(r.routeId), owner);
    if (m_server != r.server || (!r.user.isEmpty() && m_user != r.user))
        return tr("These edits belong to route %1 on %2, but this session is signed in to %3 as %4. Sign out and sign in to "
                  "%2 to restore them; until then they are kept and offered again at each start.")
            .arg(QString::number(r.routeId), owner, m_server, m_user);
    return {};
}

bool AutosaveRecovery::restore()
{
    const Offer *offer = current();
    if (!offer || !m_document)
        return false;
    if (const QString blocker = blockerOf(*offer); !blocker.isEmpty()) {
        addMessage(blocker);
        return false;
    }
    m_document->load(offer->record.baseline);
    m_document->editor()->replaceRoute(offer->record.working, tr("Restore autosaved edits"));
    // The edits now live in the document (and this instance's own autosave): keep the old file
    // as the one backup rather than delete it.
    moveAside(m_current);
    if (count() > 1)  // the dialog said so already: only the log keeps it
        qCInfo(lcAutosave).noquote() << count() - 1 << "more autosave(s) kept for the next start";
    setOffers({}); // the others would replace what was just restored: kept for the next start
    emit restored();
    return true;
}

void AutosaveRecovery::discard()
{
    if (!current())
        return;
    moveAside(m_current);
    std::vector<Offer> rest = std::move(m_offers);
    rest.erase(rest.begin() + m_current);
    const int row = m_current;
    setOffers(std::move(rest));
    setCurrentRow(row);
}

void AutosaveRecovery::postpone()
{
    if (m_postponed)
        return;
    m_postponed = true;
    emit changed();
}

void AutosaveRecovery::setOffers(std::vector<Offer> offers)
{
    beginResetModel();
    m_offers = std::move(offers);
    m_current = m_offers.empty() ? -1 : 0;
    endResetModel();
    emit changed();
}

void AutosaveRecovery::moveAside(int row)
{
    const QString path = m_directory.filePath(m_offers[size_t(row)].slot);
    QFile::remove(m_directory.discardedPath());
    if (!QFile::rename(path, m_directory.discardedPath()))
        addMessage(tr("The autosave %1 could not be moved aside.").arg(path));
}

void AutosaveRecovery::acknowledgeMessage()
{
    if (m_message.isEmpty())
        return;
    m_message.clear();
    emit messageChanged();
}

void AutosaveRecovery::addMessage(const QString &text)
{
    qCWarning(lcAutosave).noquote() << text;
    m_message = m_message.isEmpty() ? text : m_message + QLatin1Char('\n') + text;
    emit messageChanged();
}

} // namespace sortie::client
