#include "ServerHistoryRequest.h"

#include "FlightLogLog.h"
#include "HciVehicleLink.h"
#include "Messages.pb.h"
#include "ReplayController.h"
#include "VehicleFleet.h"

#include <QDateTime>

#include <algorithm>

namespace sortie::flightlog {

ServerHistoryRequest::ServerHistoryRequest(hci::HciClient *client, ReplayController *replay, QObject *parent)
    : QObject(parent)
    , m_history(client)
    , m_replay(replay)
    , m_clock([] { return QDateTime::currentMSecsSinceEpoch(); })
{
    connect(&m_history, &ServerHistory::busyChanged, this, &ServerHistoryRequest::busyChanged);
    connect(&m_history, &ServerHistory::progressChanged, this, &ServerHistoryRequest::progressChanged);
    connect(&m_history, &ServerHistory::finished, this, &ServerHistoryRequest::onFinished);
}

client::VehicleFleet *ServerHistoryRequest::fleet() const
{
    return m_fleet;
}

void ServerHistoryRequest::setFleet(client::VehicleFleet *fleet)
{
    m_fleet = fleet;
}

QString ServerHistoryRequest::timeText(qint64 ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
}

std::optional<qint64> ServerHistoryRequest::parseTime(const QString &text)
{
    // UTC, to the second or to the minute; "T" as ISO 8601 writes it is fine too.
    const QString t = text.trimmed().replace(QLatin1Char('T'), QLatin1Char(' '));
    for (const QString &format : {QStringLiteral("yyyy-MM-dd HH:mm:ss"), QStringLiteral("yyyy-MM-dd HH:mm")}) {
        QDateTime d = QDateTime::fromString(t, format);
        if (d.isValid()) {
            d.setTimeSpec(Qt::UTC);
            return d.toMSecsSinceEpoch();
        }
    }
    return std::nullopt;
}

void ServerHistoryRequest::reset()
{
    if (m_fleet) {
        const QString chosen = m_vehicleIndex >= 0 && size_t(m_vehicleIndex) < m_vehicles.size() ? m_vehicles[size_t(m_vehicleIndex)].name : QString();
        std::vector<ServerVehicle> vehicles;
        for (int row = 0; row < m_fleet->count(); ++row) {
            const vehicle::Vehicle *v = m_fleet->vehicleAt(row);
            // Only the server's vehicles have a server history (not those flown over VCI).
            if (const auto *link = v ? qobject_cast<const vehicle::HciVehicleLink *>(v->link()) : nullptr)
                vehicles.push_back({v->name(), link->vehicleObjectId()});
        }
        std::sort(vehicles.begin(), vehicles.end(), [](const auto &a, const auto &b) { return a.name.localeAwareCompare(b.name) < 0; });
        setVehicles(std::move(vehicles));
        for (size_t i = 0; i < m_vehicles.size(); ++i)
            if (m_vehicles[i].name == chosen)
                setVehicleIndex(int(i));
    }
    chooseLastHour();
    setError({});
}

void ServerHistoryRequest::chooseLastHour()
{
    // The texts hold whole seconds: round the end up, so what arrived this second is in.
    const qint64 to = (m_clock() + 999) / 1000 * 1000;
    m_toText = timeText(to);
    m_fromText = timeText(to - kDefaultSpanMs);
    emit choiceChanged();
}

void ServerHistoryRequest::setVehicles(std::vector<ServerVehicle> vehicles)
{
    m_vehicles = std::move(vehicles);
    m_vehicleIndex = m_vehicles.empty() ? -1 : 0;
    emit vehiclesChanged();
    emit choiceChanged();
}

QStringList ServerHistoryRequest::vehicleNames() const
{
    QStringList names;
    for (const ServerVehicle &v : m_vehicles)
        names.push_back(v.name);
    return names;
}

void ServerHistoryRequest::setVehicleIndex(int index)
{
    if (index == m_vehicleIndex)
        return;
    m_vehicleIndex = index;
    emit choiceChanged();
}

void ServerHistoryRequest::setFromText(const QString &text)
{
    if (text == m_fromText)
        return;
    m_fromText = text;
    emit choiceChanged();
}

void ServerHistoryRequest::setToText(const QString &text)
{
    if (text == m_toText)
        return;
    m_toText = text;
    emit choiceChanged();
}

std::optional<std::pair<qint64, qint64>> ServerHistoryRequest::range() const
{
    const auto from = parseTime(m_fromText), to = parseTime(m_toText);
    if (!from || !to)
        return std::nullopt;
    return std::make_pair(*from, *to);
}

QString ServerHistoryRequest::problem() const
{
    if (m_vehicles.empty())
        return tr("The server lists no vehicles: connect to a server first.");
    if (m_vehicleIndex < 0 || size_t(m_vehicleIndex) >= m_vehicles.size())
        return tr("Choose a vehicle.");
    const auto from = parseTime(m_fromText), to = parseTime(m_toText);
    if (!from)
        return tr("The start \"%1\" is not a time like %2 (UTC).").arg(m_fromText, timeText(m_clock()));
    if (!to)
        return tr("The end \"%1\" is not a time like %2 (UTC).").arg(m_toText, timeText(m_clock()));
    if (*from >= *to)
        return tr("The start must be before the end.");
    if (*from > m_clock())
        return tr("The start is in the future.");
    if (*to - *from > kLongestSpanMs)
        return tr("At most 24 hours at a time.");
    return {};
}

bool ServerHistoryRequest::fetch()
{
    if (!canFetch())
        return false;
    const auto [from, to] = *range();
    const ServerVehicle &v = m_vehicles[size_t(m_vehicleIndex)];
    com::ugcs::ucs::proto::Vehicle ref;
    ref.set_id(v.objectId);
    ref.set_name(v.name.toStdString());
    setError({});
    m_fetching = v.name;
    qCInfo(lcFlightLog) << "fetching the server's history of" << v.name << "from" << timeText(from) << "to" << timeText(to);
    m_history.fetch(ref, from, to);
    return true;
}

void ServerHistoryRequest::cancel()
{
    if (!m_history.isBusy())
        return;
    m_history.cancel();
    setError(tr("Cancelled."));
}

void ServerHistoryRequest::onFinished(bool ok)
{
    if (!ok) {
        setError(m_history.errorString());
        return;
    }
    std::unique_ptr<FlightLog> log = m_history.takeLog();
    if (!log || log->vehicles().empty() || log->vehicles().front().sampleCount() == 0) {
        const auto r = range();
        setError(tr("The server has no telemetry of %1 from %2 to %3 UTC.")
                     .arg(m_fetching, r ? timeText(r->first) : m_fromText, r ? timeText(r->second) : m_toText));
        return;
    }
    if (!m_replay) {
        setError(tr("There is no replay to show it in."));
        return;
    }
    m_replay->open(std::move(log));
    emit opened();
}

void ServerHistoryRequest::setError(const QString &error)
{
    if (error == m_error)
        return;
    m_error = error;
    emit errorChanged();
}

} // namespace sortie::flightlog
