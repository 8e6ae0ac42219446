#include "FlightAlerts.h"

#include "CommandLog.h"

namespace sortie::vehicle {

AlertModel::AlertModel(Subject subject, QObject *parent)
    : QAbstractListModel(parent)
    , m_subject(subject)
{
}

int AlertModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : alertCount();
}

QHash<int, QByteArray> AlertModel::roleNames() const
{
    return {{KeyRole, "key"}, {VehicleRole, "vehicle"}, {TextRole, "text"}, {InSecondsRole, "inSeconds"}, {WarningRole, "warning"}};
}

QVariant AlertModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const FlightAlert &a = alertRow(index.row());
    switch (role) {
    case KeyRole: return a.key;
    case VehicleRole: return a.vehicle;
    case InSecondsRole: return a.inSeconds;
    case WarningRole: return a.severity == FlightAlert::Severity::Warning;
    case TextRole:
    case Qt::DisplayRole: return a.text;
    default: return {};
    }
}

void AlertModel::announce(const std::vector<const FlightAlert *> &announced, const std::vector<QString> &cleared, bool rowsChanged,
                          CommandLog *log)
{
    // Copies: a slot may publish again and replace the rows these point into.
    std::vector<FlightAlert> raised;
    for (const FlightAlert *a : announced)
        raised.push_back(*a);
    if (log)
        for (const FlightAlert &a : raised)
            log->alert(a.vehicle, a.text);
    for (const FlightAlert &a : raised)
        emit alertRaised(a.key);
    for (const QString &key : cleared)
        emit alertCleared(key);
    if (rowsChanged)
        emit countChanged();
}

} // namespace sortie::vehicle
