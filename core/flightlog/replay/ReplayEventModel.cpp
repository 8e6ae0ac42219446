#include "ReplayEventModel.h"

#include "PhotoEvents.h"

#include <QDateTime>

#include <algorithm>

namespace sortie::flightlog {

void ReplayEventModel::reset(const FlightLog *log)
{
    beginResetModel();
    m_log = log;
    m_events.clear();
    if (log) {
        for (const FlightLog::Event &e : log->events()) {
            // Not the recorder's own start and stop, nor photos: a survey takes hundreds, and the
            // Photos… step places them.
            if (e.kind != QLatin1String("session") && e.kind != QLatin1String(kPhotoEventKind))
                m_events.push_back(&e);
        }
    }
    endResetModel();
    emit countChanged();
}

const FlightLog::Event *ReplayEventModel::eventAt(int row) const
{
    return row >= 0 && size_t(row) < m_events.size() ? m_events[size_t(row)] : nullptr;
}

int ReplayEventModel::nextAfter(int64_t time) const
{
    for (size_t i = 0; i < m_events.size(); ++i) {
        if (m_events[i]->time > time)
            return int(i);
    }
    return -1;
}

int ReplayEventModel::lastBefore(int64_t time) const
{
    for (size_t i = m_events.size(); i-- > 0;) {
        if (m_events[i]->time < time)
            return int(i);
    }
    return -1;
}

int ReplayEventModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_events.size());
}

QVariant ReplayEventModel::data(const QModelIndex &index, int role) const
{
    const FlightLog::Event *e = eventAt(index.row());
    if (!e || !m_log)
        return {};
    switch (role) {
    case TimeRole: return QVariant::fromValue<qint64>(e->time);
    case TimeTextRole: return QDateTime::fromMSecsSinceEpoch(e->time, Qt::UTC).toString(QStringLiteral("HH:mm:ss"));
    case KindRole: return e->kind;
    case Qt::DisplayRole:
    case TextRole: return e->text;
    case VehicleRole: return e->vehicle >= 0 ? m_log->vehicles()[size_t(e->vehicle)].name() : QString();
    case FractionRole: {
        const double span = double(m_log->end() - m_log->start());
        return span > 0 ? std::clamp(double(e->time - m_log->start()) / span, 0.0, 1.0) : 0.0;
    }
    case FailedRole: return e->ok == 0;
    default: return {};
    }
}

QHash<int, QByteArray> ReplayEventModel::roleNames() const
{
    return {{TimeRole, "time"}, {TimeTextRole, "timeText"}, {KindRole, "kind"}, {TextRole, "text"},
            {VehicleRole, "vehicle"}, {FractionRole, "fraction"}, {FailedRole, "failed"}};
}

} // namespace sortie::flightlog
