#include "ServerObjectListModel.h"

namespace sortie::client {

ServerObjectListModel::ServerObjectListModel(QObject *parent)
    : QAbstractListModel(parent)
{
}

int ServerObjectListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QVariant ServerObjectListModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const Entry &entry = m_entries[size_t(index.row())];
    switch (role) {
    case ObjectIdRole: return entry.objectId;
    case NameRole:
    case Qt::DisplayRole: return entry.name;
    case DetailRole: return entry.detail;
    default: return {};
    }
}

QHash<int, QByteArray> ServerObjectListModel::roleNames() const
{
    return {{ObjectIdRole, "objectId"}, {NameRole, "name"}, {DetailRole, "detail"}};
}

void ServerObjectListModel::setEntries(std::vector<Entry> entries)
{
    const int before = count();
    beginResetModel();
    m_entries = std::move(entries);
    endResetModel();
    if (before != count())
        emit countChanged();
}

int ServerObjectListModel::rowOf(int objectId) const
{
    for (size_t i = 0; i < m_entries.size(); ++i) {
        if (m_entries[i].objectId == objectId)
            return int(i);
    }
    return -1;
}

int ServerObjectListModel::objectIdAt(int row) const
{
    return row >= 0 && row < count() ? m_entries[size_t(row)].objectId : -1;
}

QString ServerObjectListModel::nameAt(int row) const
{
    return row >= 0 && row < count() ? m_entries[size_t(row)].name : QString();
}

} // namespace sortie::client
