#pragma once

#include <QAbstractListModel>

namespace sortie::airspace {

class Airspace;

// The store's zones for a list view, one row per zone in the store's order: name, kind, where it
// came from, floor and ceiling as text, the operator's active switch (editable), whether it is
// drawn here (so editable on the map), why it cannot be checked, and whether it is the chosen one.
class ZoneListModel : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY countChanged)

public:
    enum Roles {
        NameRole = Qt::UserRole + 1,
        KindRole,        // "exclusion" / "inclusion"
        SourceRole,      // "drawn", "server aerodrome", "server custom", "file", "route fence"
        OriginRole,      // the file and feature, the server object
        FloorRole,       // "ground", "30 m AGL"
        CeilingRole,     // "unlimited", "150 m AMSL"
        ActiveRole,      // editable
        CustomRole,      // drawn here: edited on the map
        ProblemRole,     // why it is not checked; empty when it is
        SelectedRole,
    };

    explicit ZoneListModel(Airspace *store);

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QHash<int, QByteArray> roleNames() const override;
    int count() const { return rowCount(); }

    // The store rebuilt its set; it had `before` zones.
    void rebuilt(int before);

signals:
    void countChanged();

private:
    Airspace *m_store;
    int m_selected = -1;
};

} // namespace sortie::airspace
