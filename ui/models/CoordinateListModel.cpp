#include "CoordinateListModel.h"

namespace sortie::ui {

CoordinateListModel::CoordinateListModel(QObject *parent)
    : QAbstractListModel(parent)
{
}

int CoordinateListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QVariant CoordinateListModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const QGeoCoordinate &point = m_points[size_t(index.row())];
    switch (role) {
    case LatitudeRole: return point.latitude();
    case LongitudeRole: return point.longitude();
    case AltitudeRole: return std::isnan(point.altitude()) ? 0.0 : point.altitude();
    case Qt::DisplayRole: return point.toString(QGeoCoordinate::DegreesWithHemisphere);
    default: return {};
    }
}

bool CoordinateListModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return false;
    bool ok = false;
    const double number = value.toDouble(&ok);
    if (!ok)
        return false;
    QGeoCoordinate &point = m_points[size_t(index.row())];
    switch (role) {
    case LatitudeRole:
        if (number < -90 || number > 90)
            return false;
        point.setLatitude(number);
        break;
    case LongitudeRole:
        if (number < -180 || number > 180)
            return false;
        point.setLongitude(number);
        break;
    case AltitudeRole: point.setAltitude(number); break;
    default: return false;
    }
    emit dataChanged(index, index, {role});
    return true;
}

Qt::ItemFlags CoordinateListModel::flags(const QModelIndex &index) const
{
    return QAbstractListModel::flags(index) | Qt::ItemIsEditable;
}

QHash<int, QByteArray> CoordinateListModel::roleNames() const
{
    return {{LatitudeRole, "latitude"}, {LongitudeRole, "longitude"}, {AltitudeRole, "altitude"}};
}

void CoordinateListModel::append(double latitude, double longitude, double altitude)
{
    insert(count(), latitude, longitude, altitude);
}

void CoordinateListModel::insert(int row, double latitude, double longitude, double altitude)
{
    row = std::clamp(row, 0, count());
    beginInsertRows({}, row, row);
    m_points.insert(m_points.begin() + row, QGeoCoordinate(latitude, longitude, altitude));
    endInsertRows();
    emit countChanged();
}

bool CoordinateListModel::setCoordinate(int row, double latitude, double longitude)
{
    if (row < 0 || row >= count() || latitude < -90 || latitude > 90)
        return false;
    m_points[size_t(row)].setLatitude(latitude);
    m_points[size_t(row)].setLongitude(longitude);
    const QModelIndex changed = index(row);
    emit dataChanged(changed, changed, {LatitudeRole, LongitudeRole});
    return true;
}

bool CoordinateListModel::remove(int row)
{
    if (row < 0 || row >= count())
        return false;
    beginRemoveRows({}, row, row);
    m_points.erase(m_points.begin() + row);
    endRemoveRows();
    emit countChanged();
    return true;
}

void CoordinateListModel::clear()
{
    assign({});
}

QGeoCoordinate CoordinateListModel::get(int row) const
{
    return row >= 0 && row < count() ? m_points[size_t(row)] : QGeoCoordinate();
}

QList<QGeoCoordinate> CoordinateListModel::coordinates() const
{
    return QList<QGeoCoordinate>(m_points.begin(), m_points.end());
}

void CoordinateListModel::assign(std::vector<QGeoCoordinate> points)
{
    beginResetModel();
    m_points = std::move(points);
    endResetModel();
    emit countChanged();
}

} // namespace sortie::ui
