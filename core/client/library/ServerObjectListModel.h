#pragma once

#include <QAbstractListModel>

#include <vector>

namespace sortie::client {

// A list of server objects (routes, vehicles) for a picker: id, name and one line of detail.
class ServerObjectListModel : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY countChanged)

public:
    enum Roles { ObjectIdRole = Qt::UserRole + 1, NameRole, DetailRole };

    struct Entry
    {
        int objectId = 0;
        QString name;
        QString detail;
    };

    explicit ServerObjectListModel(QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

    int count() const { return int(m_entries.size()); }
    void setEntries(std::vector<Entry> entries);
    const std::vector<Entry> &entries() const { return m_entries; }
    Q_INVOKABLE int rowOf(int objectId) const;
    Q_INVOKABLE int objectIdAt(int row) const;
    Q_INVOKABLE QString nameAt(int row) const;

signals:
    void countChanged();

private:
    std::vector<Entry> m_entries;
};

} // namespace sortie::client
