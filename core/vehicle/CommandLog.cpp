#include "CommandLog.h"

#include "VehicleLog.h"

#include <QPointer>

namespace sortie::vehicle {

CommandLog::CommandLog(QObject *parent, int capacity)
    : QAbstractListModel(parent)
    , m_capacity(std::max(1, capacity))
{
}

int CommandLog::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QHash<int, QByteArray> CommandLog::roleNames() const
{
    return {{TimeRole, "time"}, {TimeTextRole, "timeText"}, {VehicleRole, "vehicle"}, {CommandRole, "command"},
            {StatusRole, "status"}, {StatusTextRole, "statusText"}, {ResultRole, "result"}, {TextRole, "text"}, {FailedRole, "failed"}};
}

QString CommandLog::statusText(Status status)
{
    switch (status) {
    case Status::Pending: return tr("sent");
    case Status::Done: return tr("done");
    case Status::Failed: return tr("failed");
    case Status::Cancelled: return tr("cancelled");
    case Status::Alert: return tr("alert");
    }
    return {};
}

QVariant CommandLog::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const Entry &e = m_entries[size_t(index.row())];
    switch (role) {
    case TimeRole: return e.sent;
    case TimeTextRole: return e.sent.toLocalTime().toString(QStringLiteral("HH:mm:ss"));
    case VehicleRole: return e.vehicle;
    case CommandRole: return e.command;
    case StatusRole: return int(e.status);
    case StatusTextRole: return statusText(e.status);
    case ResultRole: return e.result;
    case FailedRole: return e.status == Status::Failed || e.status == Status::Alert;
    case TextRole:
    case Qt::DisplayRole:
        return e.result.isEmpty() ? tr("%1 %2: %3 %4").arg(e.sent.toLocalTime().toString(QStringLiteral("HH:mm:ss")), e.vehicle, e.command, statusText(e.status))
                                  : tr("%1 %2: %3 %4: %5").arg(e.sent.toLocalTime().toString(QStringLiteral("HH:mm:ss")), e.vehicle, e.command,
                                                               statusText(e.status), e.result);
    default: return {};
    }
}

int CommandLog::rowOf(int id) const
{
    // Ids grow with the rows, so the row is found from the first id.
    if (m_entries.empty())
        return -1;
    const int row = id - m_entries.front().id;
    return row >= 0 && row < count() ? row : -1;
}

const CommandLog::Entry *CommandLog::find(int id) const
{
    const int row = rowOf(id);
    return row < 0 ? nullptr : &m_entries[size_t(row)];
}

CommandLog::Entry &CommandLog::append(const QString &vehicle, const QString &command)
{
    if (count() >= m_capacity) {
        beginRemoveRows({}, 0, 0);
        m_entries.pop_front();
        endRemoveRows();
    }
    Entry e;
    e.id = m_nextId++;
    e.sent = QDateTime::currentDateTimeUtc();
    e.vehicle = vehicle;
    e.command = command;
    beginInsertRows({}, count(), count());
    m_entries.push_back(e);
    endInsertRows();
    emit countChanged();
    return m_entries.back();
}

int CommandLog::begin(const QString &vehicle, const QString &command)
{
    const Entry &e = append(vehicle, command);
    qCInfo(lcVehicle).noquote() << vehicle << "<-" << command;
    emit recorded(e);
    return e.id;
}

int CommandLog::alert(const QString &vehicle, const QString &text)
{
    Entry &e = append(vehicle, text);
    e.answered = e.sent;
    e.status = Status::Alert;
    qCWarning(lcVehicle).noquote() << vehicle << "alert:" << text;
    emit recorded(e);
    emit finished(e);
    return e.id;
}

void CommandLog::finish(int id, const CommandResult &result)
{
    const int row = rowOf(id);
    if (row < 0)
        return;
    Entry &e = m_entries[size_t(row)];
    if (e.status != Status::Pending)
        return;
    e.answered = QDateTime::currentDateTimeUtc();
    e.status = result.ok ? Status::Done : result.cancelled ? Status::Cancelled : Status::Failed;
    e.result = result.ok ? QString() : result.message;
    if (result.ok)
        qCInfo(lcVehicle).noquote() << e.vehicle << "<-" << e.command << "done in" << e.sent.msecsTo(e.answered) << "ms";
    else
        qCWarning(lcVehicle).noquote() << e.vehicle << "<-" << e.command << statusText(e.status) << ":" << result.message;
    emit dataChanged(index(row), index(row));
    emit finished(e);
}

std::function<void(const CommandResult &)> CommandLog::track(const QString &vehicle, const QString &command)
{
    const int id = begin(vehicle, command);
    return [self = QPointer<CommandLog>(this), id](const CommandResult &result) {
        if (self)
            self->finish(id, result);
    };
}

} // namespace sortie::vehicle
