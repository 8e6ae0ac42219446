#include "ModelCoordinates.h"

#include "WebMercator.h"

#include <QAbstractItemModel>

#include <cmath>
#include <limits>

namespace sortie::ui {

ModelCoordinates::ModelCoordinates(QObject *parent)
    : QObject(parent)
{
}

void ModelCoordinates::setModel(QAbstractItemModel *model)
{
    if (model == m_model)
        return;
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = model;
    if (m_model) {
        connect(m_model, &QAbstractItemModel::dataChanged, this,
                [this](const QModelIndex &topLeft, const QModelIndex &bottomRight, const QList<int> &roles) {
                    if (roles.isEmpty() || roles.contains(m_latitudeId) || roles.contains(m_longitudeId))
                        reloadRows(topLeft.row(), bottomRight.row());
                });
        connect(m_model, &QAbstractItemModel::rowsInserted, this, &ModelCoordinates::reload);
        connect(m_model, &QAbstractItemModel::rowsRemoved, this, &ModelCoordinates::reload);
        connect(m_model, &QAbstractItemModel::rowsMoved, this, &ModelCoordinates::reload);
        connect(m_model, &QAbstractItemModel::modelReset, this, &ModelCoordinates::reload);
        connect(m_model, &QAbstractItemModel::layoutChanged, this, &ModelCoordinates::reload);
        connect(m_model, &QObject::destroyed, this, [this] { setModel(nullptr); });
    }
    reload();
}

void ModelCoordinates::setRoleNames(const QByteArray &latitude, const QByteArray &longitude)
{
    m_latitudeRole = latitude;
    m_longitudeRole = longitude;
    reload();
}

int ModelCoordinates::roleId(const QByteArray &name) const
{
    if (!m_model)
        return -1;
    const QHash<int, QByteArray> roles = m_model->roleNames();
    for (auto it = roles.cbegin(); it != roles.cend(); ++it) {
        if (it.value() == name)
            return it.key();
    }
    return -1;
}

void ModelCoordinates::resolveRoles()
{
    m_latitudeId = roleId(m_latitudeRole);
    m_longitudeId = roleId(m_longitudeRole);
}

bool ModelCoordinates::isValid(int row) const
{
    return row >= 0 && row < count() && !std::isnan(m_points[size_t(row)].x());
}

void ModelCoordinates::reload()
{
    resolveRoles();
    m_points.assign(m_model ? size_t(m_model->rowCount()) : 0, QPointF());
    if (!m_points.empty())
        reloadRows(0, count() - 1);
    else
        emit changed(0, -1);
}

void ModelCoordinates::reloadRows(int first, int last)
{
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    first = std::max(first, 0);
    last = std::min(last, count() - 1);
    for (int row = first; row <= last; ++row) {
        QPointF point(nan, nan);
        if (m_model && m_latitudeId >= 0 && m_longitudeId >= 0) {
            const QModelIndex index = m_model->index(row, 0);
            bool okLat = false;
            bool okLon = false;
            const double lat = m_model->data(index, m_latitudeId).toDouble(&okLat);
            const double lon = m_model->data(index, m_longitudeId).toDouble(&okLon);
            if (okLat && okLon && std::isfinite(lat) && std::isfinite(lon) && std::abs(lat) <= 90.0)
                point = WebMercator::project(lat, lon);
        }
        m_points[size_t(row)] = point;
    }
    emit changed(first, last);
}

} // namespace sortie::ui
