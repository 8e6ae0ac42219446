#include "ServerHistory.h"

#include "FlightLogLog.h"
#include "HciClient.h"
#include "Messages.pb.h"
#include "HciReply.h"
#include "HciTelemetryMapper.h"

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
    m_from = fromMs;
    m_to = std::max(fromMs, toMs);
    m_limit = std::max(1, pageLimit);
    m_updates.clear();
    m_log.reset();
    m_error.clear();
    m_pages = 0;
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
    const auto &response = reply->response<pb::GetTelemetryResponse>();
    const int64_t now = QDateTime::currentMSecsSinceEpoch();
    for (const pb::Telemetry &t : response.telemetry())
        vehicle::appendHciTelemetry(t, now, m_updates);
    ++m_pages;
    // Go on from where the server says, as long as that moves forward.
    qint64 next = -1;
    if (response.has_nexttelemetrytime() && response.nexttelemetrytime() > m_from && response.nexttelemetrytime() <= m_to)
        next = response.nexttelemetrytime();
    m_progress = next < 0 || m_to <= m_from ? 1.0 : double(next - m_from) / double(m_to - m_from);
    emit progressChanged();
    if (next >= 0 && response.telemetry_size() > 0) {
        m_from = std::max(m_from, next);
        request(next);
        return;
    }
    finish(true);
}

void ServerHistory::finish(bool ok, const QString &error)
{
    m_error = error;
    if (ok) {
        // One block per second of the vehicle's time, like a recording.
        std::stable_sort(m_updates.begin(), m_updates.end(), [](const auto &a, const auto &b) { return a.time < b.time; });
        FlightLog::Vehicle v;
        v.key = QStringLiteral("HCI:%1").arg(m_vehicle->id());
        v.identity.id = QString::number(m_vehicle->id());
        v.identity.name = QString::fromStdString(m_vehicle->name());
        v.identity.protocol = QStringLiteral("HCI");
        BlockFields fields;
        std::array<int, vehicle::kTelemetryFieldCount> slot;
        slot.fill(-1);
        int64_t blockStart = 0;
        auto close = [&] {
            if (!fields.empty())
                v.appendBlock(TelemetryBlockCodec::encode(fields));
            fields.clear();
            slot.fill(-1);
        };
        for (const vehicle::TelemetryUpdate &u : m_updates) {
            if (!fields.empty() && u.time - blockStart >= 1000)
                close();
            if (fields.empty())
                blockStart = u.time;
            int &s = slot[size_t(u.field)];
            if (s < 0) {
                s = int(fields.size());
                fields.push_back({u.field, {}});
            }
            fields[size_t(s)].samples.push_back({u.time, u.value});
        }
        close();
        m_log = std::make_unique<FlightLog>();
        m_log->addVehicle(std::move(v));
        m_log->finish();
        qCInfo(lcFlightLog) << "server history of" << m_vehicle->name().c_str() << m_updates.size() << "values in" << m_pages << "pages";
    }
    m_updates.clear();
    m_updates.shrink_to_fit();
    emit busyChanged();
    emit finished(ok);
}

std::unique_ptr<FlightLog> ServerHistory::takeLog()
{
    return std::move(m_log);
}

} // namespace sortie::flightlog
