#include "ServerZoneReply.h"

#include <QTimer>
#include <QCoreApplication>

namespace sortie::airspace {

ServerZoneReply::ServerZoneReply(QObject *parent)
    : QObject(parent)
{
}

void ServerZoneReply::succeed(Zone zone)
{
    if (m_finished)
        return;
    m_zone = std::move(zone);
    finish();
}

void ServerZoneReply::fail(const QString &error)
{
    if (m_finished)
        return;
    m_error = error.isEmpty() ? QCoreApplication::translate("ServerZoneReply", "the server gave no reason") : error;
    finish();
}

void ServerZoneReply::finish()
{
    m_finished = true;
    // Queued: a reply that fails at once (not connected, a zone the server cannot hold) still
    // reaches a caller that connects after save() or remove() returned.
    QTimer::singleShot(0, this, [this] {
        emit finished();
        deleteLater();
    });
}

} // namespace sortie::airspace
