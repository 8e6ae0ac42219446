#include "RouteAutosave.h"

#include "AtomicFile.h"
#include "AutosaveRecord.h"
#include "Messages.pb.h"
#include "RouteDocument.h"

#include <QFile>
#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcAutosave, "sortie.client.autosave")

namespace sortie::client {

RouteAutosave::RouteAutosave(RouteDocument *document, const QString &directory, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_directory(directory)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(500);
    connect(&m_timer, &QTimer::timeout, this, [this] { writeNow(); });
    QString error;
    if (!m_directory.ensureExists(&error)) {
        fail(error);
        return;
    }
    std::tie(m_slot, m_lock) = m_directory.claimFreeSlot();
    if (!m_lock) {
        fail(tr("No free autosave slot in %1: edits are not autosaved.").arg(directory));
        return;
    }
    QUndoStack *stack = document->undoStack();
    connect(stack, &QUndoStack::indexChanged, this, &RouteAutosave::edited);
    connect(stack, &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean)
            takeBaseline();
    });
    connect(document, &RouteDocument::loaded, this, &RouteAutosave::takeBaseline);
    takeBaseline();
    qCInfo(lcAutosave).noquote() << "autosaving to" << filePath();
}

RouteAutosave::~RouteAutosave()
{
    if (!m_lock)
        return;
    if (m_document && m_document->isModified())
        writeNow(); // kept: the next start offers these edits
    else
        remove();
}

QString RouteAutosave::filePath() const
{
    return m_slot > 0 ? m_directory.filePath(m_slot) : QString();
}

void RouteAutosave::setServer(const QString &address, const QString &user)
{
    m_server = address;
    m_user = user;
}

void RouteAutosave::edited()
{
    if (!m_document)
        return;
    if (m_document->isModified())
        m_timer.start(); // restarted by every edit of a burst: one write after it
}

void RouteAutosave::takeBaseline()
{
    m_timer.stop();
    if (!m_document)
        return;
    m_baseline = encodeAutosaveRoute(m_document->route());
    remove();
}

bool RouteAutosave::writeNow()
{
    m_timer.stop();
    if (!m_lock || !m_document || !m_document->isModified())
        return false;
    AutosaveRecord header;
    header.server = m_server;
    header.user = m_user;
    if (const auto &origin = m_document->route().origin) {
        header.routeId = origin.message->has_id() ? origin.message->id() : -1;
        header.routeVersion = origin.message->has_version() ? origin.message->version() : -1;
    }
    header.savedAt = QDateTime::currentDateTimeUtc();
    const QByteArray data = encodeAutosave(header, encodeAutosaveRoute(m_document->route()), m_baseline);
    const QString error = writeFileAtomically(filePath(), data);
    if (!error.isEmpty()) {
        fail(error);
        return false;
    }
    m_error.clear();
    emit written(filePath());
    return true;
}

void RouteAutosave::remove()
{
    if (m_slot > 0 && QFile::exists(filePath()) && QFile::remove(filePath()))
        emit removed();
}

void RouteAutosave::fail(const QString &message)
{
    m_error = message;
    qCWarning(lcAutosave).noquote() << message;
    emit failed(message);
}

} // namespace sortie::client
