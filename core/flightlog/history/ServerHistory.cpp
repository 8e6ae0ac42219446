#include "ServerHistory.h"

#include "FlightLogLog.h"
#include "HistoryPages.h"
#include "HciClient.h"
#include "Messages.pb.h"
#include "HciReply.h"

#include <QDateTime>

#include <algorithm>

namespace sortie::flightlog {

namespace pb = com::ugcs::ucs::proto;

ServerHistory::ServerHistory(hci::HciClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
}

ServerHistory::~ServerHistory()
{
    cancel();
}

void ServerHistory::fetch(const pb::Vehicle &vehicle, qint64 fromMs, qint64 toMs, int pageLimit)
{
    cancel();
    m_vehicle = std::make_unique<pb::Vehicle>(vehicle);
    m_to = std::max(fromMs, toMs);
    m_limit = std::max(1, pageLimit);
    m_pages = std::make_unique<HistoryPages>(fromMs, m_to);
    m_log.reset();
    m_error.clear();
    m_pageCount = 0;
    m_progress = 0;
    emit progressChanged();
    request(fromMs);
    emit busyChanged();
}

void ServerHistory::cancel()
{
    if (!m_reply)
        return;
    disconnect(m_reply, nullptr, this, nullptr);
    // The reply deletes itself when its answer comes; nothing listens to it any more.
    m_reply = nullptr;
    emit busyChanged();
}

void ServerHistory::request(qint64 fromMs)
{
    if (!m_client) {
        finish(false, tr("not connected to a server"));
        return;
    }
    m_reply = m_client->telemetryHistory(*m_vehicle, fromMs, m_to, m_limit);
    connect(m_reply, &hci::HciReply::finished, this, &ServerHistory::onReply);
}

void ServerHistory::onReply()
{
    hci::HciReply *reply = m_reply;
    m_reply = nullptr;
    if (!reply)
        return;
    if (!reply->isOk()) {
        finish(false, tr("The server's history could not be read: %1").arg(reply->error().message()));
        return;
    }
    const auto next = m_pages->add(reply->response<pb::GetTelemetryResponse>(), QDateTime::currentMSecsSinceEpoch());
    ++m_pageCount;
    m_progress = m_pages->progress();
    emit progressChanged();
    if (next) {
        request(*next);
        return;
    }
    finish(true);
}

void ServerHistory::finish(bool ok, const QString &error)
{
    m_error = error;
    if (ok) {
        qCInfo(lcFlightLog) << "server history of" << m_vehicle->name().c_str() << m_pages->valueCount() << "values in" << m_pageCount
                            << "pages" << m_pages->outOfRange() << "out of the range left out";
        m_log = m_pages->takeLog(*m_vehicle);
    }
    m_pages.reset();
    emit busyChanged();
    emit finished(ok);
}

std::unique_ptr<FlightLog> ServerHistory::takeLog()
{
    return std::move(m_log);
}

} // namespace sortie::flightlog
