#include "ZoneListModel.h"

#include "Airspace.h"

namespace sortie::airspace {

ZoneListModel::ZoneListModel(Airspace *store)
    : QAbstractListModel(store), m_store(store)
{
    connect(store, &Airspace::selectedZoneChanged, this, [this] {
        const int before = m_selected;
        m_selected = m_store->selectedZone();
        for (const int row : {before, m_selected})
            if (row >= 0 && row < rowCount())
                emit dataChanged(index(row), index(row), {SelectedRole});
    });
}

int ZoneListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : m_store->count();
}

QVariant ZoneListModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const int row = index.row();
    const Zone &z = m_store->zoneAt(row);
    const Airspace::Group group = m_store->groupOf(row);
    switch (role) {
    case Qt::DisplayRole:
    case NameRole: return z.name;
    case KindRole: return kindName(z.kind);
    case SourceRole:
        return group == Airspace::Group::Server ? sourceName(z.source) : Airspace::groupName(group);
    case OriginRole: return z.origin;
    case FloorRole: return limitText(z.floor, false);
    case CeilingRole: return limitText(z.ceiling, true);
    case ActiveRole: return z.active;
    case CustomRole: return group == Airspace::Group::Custom;
    case ProblemRole: return m_store->problemOf(row);
    case SelectedRole: return row == m_store->selectedZone();
    }
    return {};
}

bool ZoneListModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!index.isValid() || role != ActiveRole)
        return false;
    m_store->setActive(index.row(), value.toBool());
    return true;
}

Qt::ItemFlags ZoneListModel::flags(const QModelIndex &index) const
{
    return QAbstractListModel::flags(index) | Qt::ItemIsEditable;
}

QHash<int, QByteArray> ZoneListModel::roleNames() const
{
    return {{NameRole, "name"},       {KindRole, "kind"},         {SourceRole, "source"},   {OriginRole, "origin"},
            {FloorRole, "floor"},     {CeilingRole, "ceiling"},   {ActiveRole, "active"},   {CustomRole, "custom"},
            {ProblemRole, "problem"}, {SelectedRole, "selected"}};
}

void ZoneListModel::rebuilt(int before)
{
    // Dragging a drawn zone's corner changes one zone many times: the rows stay, their data change.
    if (before == rowCount()) {
        if (before > 0)
            emit dataChanged(index(0), index(before - 1));
        return;
    }
    beginResetModel();
    endResetModel();
    emit countChanged();
}

} // namespace sortie::airspace
