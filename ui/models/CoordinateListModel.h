#pragma once

#include <QAbstractListModel>
#include <QGeoCoordinate>
#include <QtQml/qqmlregistration.h>

#include <vector>

namespace sortie::ui {

// A plain editable list of coordinates with latitude, longitude and altitude roles: what map
// layers take when no mission model is at hand (an area polygon being drawn, a measured line).
class CoordinateListModel : public QAbstractListModel
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(int count READ count NOTIFY countChanged)

public:
    enum Role { LatitudeRole = Qt::UserRole + 1, LongitudeRole, AltitudeRole };

    explicit CoordinateListModel(QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QHash<int, QByteArray> roleNames() const override;

    int count() const { return int(m_points.size()); }
    Q_INVOKABLE void append(double latitude, double longitude, double altitude = 0);
    Q_INVOKABLE void insert(int row, double latitude, double longitude, double altitude = 0);
    Q_INVOKABLE bool setCoordinate(int row, double latitude, double longitude);
    Q_INVOKABLE bool remove(int row);
    Q_INVOKABLE void clear();
    Q_INVOKABLE QGeoCoordinate get(int row) const;
    // Every point (what RouteEditor::addAreaScan takes).
    Q_INVOKABLE QList<QGeoCoordinate> coordinates() const;
    // Replaces everything at once (one reset, not one signal per point).
    void assign(std::vector<QGeoCoordinate> points);

signals:
    void countChanged();

private:
    std::vector<QGeoCoordinate> m_points;
};

} // namespace sortie::ui
