#include "RouteAutosave.h"

#include "AutosaveRecord.h"
#include "AutosaveWriter.h"
#include "HciOrigin.h"
#include "Messages.pb.h"
#include "RouteDocument.h"

#include <QLoggingCategory>

#include <utility>

Q_LOGGING_CATEGORY(lcAutosave, "sortie.client.autosave")

namespace sortie::client {

RouteAutosave::RouteAutosave(RouteDocument *document, const QString &directory, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_directory(directory)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(500);
    connect(&m_timer, &QTimer::timeout, this, &RouteAutosave::writeLater);
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
    m_writer = new AutosaveWriter(filePath());
    m_writer->moveToThread(&m_thread);
    // Emitted on the writer's thread, delivered here in the order they were emitted.
    connect(m_writer, &AutosaveWriter::written, this, [this](const QString &path) {
        m_error.clear();
        emit written(path);
    });
    connect(m_writer, &AutosaveWriter::removed, this, &RouteAutosave::removed);
    connect(m_writer, &AutosaveWriter::failed, this, &RouteAutosave::fail);
    m_thread.setObjectName(QStringLiteral("autosave writer %1").arg(m_slot));
    m_thread.start();

    QUndoStack *stack = document->undoStack();
    connect(stack, &QUndoStack::indexChanged, this, &RouteAutosave::edited);
    connect(stack, &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean)
            takeBaseline();
    });
    connect(document, &RouteDocument::loaded, this, &RouteAutosave::takeBaseline);
    connect(document, &RouteDocument::baselineChanged, this, [this] { m_baselineMoved = true; });
    takeBaseline();
    qCInfo(lcAutosave).noquote() << "autosaving to" << filePath();
}

RouteAutosave::~RouteAutosave()
{
    if (!m_lock)
        return;
    if (m_document && m_document->isModified()) {
        if (!writeNow()) // kept: the next start offers these edits
            qCWarning(lcAutosave).noquote() << m_error;
    } else {
        if (m_writer->queueRemove())
            drainLater();
        waitForWriter();
    }
    m_thread.quit();
    m_thread.wait();
    delete m_writer; // its thread has stopped; the lock is released after this, with the members
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
    if (!m_writer || !m_document)
        return;
    // The file goes and the route as it is now becomes the baseline, both after any write still
    // queued or running: a late write cannot bring the file back.
    m_baselineMoved = false;
    if (m_writer->queueRemove(m_document->route()))
        drainLater();
}

bool RouteAutosave::queueWrite()
{
    m_timer.stop();
    if (!m_writer || !m_document || !m_document->isModified())
        return false;
    AutosaveRecord header;
    header.server = m_server;
    header.user = m_user;
    if (const auto &origin = m_document->route().origin) {
        header.routeId = hciRoute(origin)->has_id() ? hciRoute(origin)->id() : -1;
        header.routeVersion = hciRoute(origin)->has_version() ? hciRoute(origin)->version() : -1;
    }
    header.savedAt = QDateTime::currentDateTimeUtc();
    // A copy of the value: the worker encodes it while the GUI goes on editing the original.
    std::optional<mission::Route> baseline;
    if (std::exchange(m_baselineMoved, false))
        baseline = m_document->baseline();
    return m_writer->queueWrite(std::move(header), m_document->route(), std::move(baseline));
}

void RouteAutosave::writeLater()
{
    if (queueWrite())
        drainLater();
}

void RouteAutosave::drainLater()
{
    QMetaObject::invokeMethod(m_writer, [writer = m_writer] { writer->drain(); }, Qt::QueuedConnection);
}

QString RouteAutosave::drainAndWait()
{
    // Runs after every drain already posted (events are delivered in order), then drains the rest.
    QString error;
    QMetaObject::invokeMethod(m_writer, [&error, writer = m_writer] { error = writer->drain(); }, Qt::BlockingQueuedConnection);
    return error;
}

bool RouteAutosave::writeNow()
{
    m_timer.stop();
    if (!m_writer || !m_document || !m_document->isModified())
        return false;
    queueWrite(); // drainAndWait() below runs it, whether or not a drain was posted
    const QString error = drainAndWait();
    m_error = error; // the signals (written or failed) follow through the event loop
    return error.isEmpty();
}

void RouteAutosave::waitForWriter()
{
    if (m_writer)
        drainAndWait();
}

void RouteAutosave::fail(const QString &message)
{
    m_error = message;
    qCWarning(lcAutosave).noquote() << message;
    emit failed(message);
}

} // namespace sortie::client
