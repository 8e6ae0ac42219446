#include "AutosaveRecovery.h"

#include "RouteDiff.h"
#include "RouteDocument.h"

#include <QFile>
#include <QFileInfo>
#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcAutosave)

namespace sortie::client {

using namespace sortie::mission;

AutosaveRecovery::AutosaveRecovery(RouteDocument *document, const QString &directory, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_directory(directory)
{
    scan();
}

AutosaveRecovery::~AutosaveRecovery() = default;

void AutosaveRecovery::scan()
{
    release();
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
            addMessage(moved ? tr("The autosaved edits in %1 cannot be read (%2). The file was kept as %3.")
                                   .arg(path, decoded.error().withFile(QFileInfo(path).fileName()).toString(), aside)
                             : tr("The autosaved edits in %1 cannot be read (%2).").arg(path, decoded.error().withFile(QFileInfo(path).fileName()).toString()));
            continue;
        }
        m_slot = slot;
        m_lock = std::move(lock);
        m_record = std::move(decoded).value();
        const RouteDiff diff = RouteDiff::compare(m_record->baseline, m_record->working);
        m_changes = diff.texts();
        m_summary = diff.summary();
        qCInfo(lcAutosave).noquote() << "offering" << path << ":" << m_summary;
        break;
    }
    emit changed();
}

QString AutosaveRecovery::routeName() const
{
    if (!m_record)
        return {};
    const QString name = m_record->working.settings.name;
    return name.isEmpty() ? tr("Untitled route") : name;
}

QString AutosaveRecovery::origin() const
{
    if (!m_record || m_record->routeId < 0)
        return {};
    QString text = tr("route %1, version %2").arg(m_record->routeId).arg(m_record->routeVersion);
    if (!m_record->server.isEmpty())
        text += tr(", on %1").arg(m_record->server);
    if (!m_record->user.isEmpty())
        text += tr(" as %1").arg(m_record->user);
    return text;
}

bool AutosaveRecovery::restore()
{
    if (!m_record || !m_document)
        return false;
    m_document->load(m_record->baseline);
    m_document->editor()->replaceRoute(m_record->working, tr("Restore autosaved edits"));
    // The edits now live in the document (and this instance's own autosave): keep the old file
    // as the one backup rather than delete it.
    QFile::remove(m_directory.discardedPath());
    QFile::rename(m_directory.filePath(m_slot), m_directory.discardedPath());
    emit restored();
    scan();
    return true;
}

void AutosaveRecovery::discard()
{
    if (!m_record)
        return;
    QFile::remove(m_directory.discardedPath());
    if (!QFile::rename(m_directory.filePath(m_slot), m_directory.discardedPath()))
        addMessage(tr("The autosave %1 could not be moved aside.").arg(m_directory.filePath(m_slot)));
    scan();
}

void AutosaveRecovery::release()
{
    m_lock.reset();
    m_slot = -1;
    m_record.reset();
    m_changes.clear();
    m_summary.clear();
}

void AutosaveRecovery::addMessage(const QString &text)
{
    qCWarning(lcAutosave).noquote() << text;
    m_message = m_message.isEmpty() ? text : m_message + QLatin1Char('\n') + text;
    emit messageChanged();
}

} // namespace sortie::client
