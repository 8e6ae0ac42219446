#include "VehicleModelReader.h"

#include "VehiclePalette.h"
#include "WebMercator.h"

#include <QAbstractItemModel>

namespace sortie::ui {

void VehicleModelReader::resolve(const QAbstractItemModel *model, const VehicleRoleNames &names)
{
    m_names = names;
    m_roles.clear();
    if (!model)
        return;
    const QHash<int, QByteArray> roleNames = model->roleNames();
    for (auto it = roleNames.cbegin(); it != roleNames.cend(); ++it)
        m_roles.insert(QString::fromUtf8(it.value()), it.key());
}

VehicleMark VehicleModelReader::read(const QAbstractItemModel &model, int row) const
{
    VehicleMark vehicle;
    const QModelIndex index = model.index(row, 0);
    auto value = [&](const QString &role) {
        const auto it = m_roles.constFind(role);
        return it == m_roles.cend() ? QVariant() : model.data(index, it.value());
    };
    auto number = [&](const QString &role, bool *ok) { return value(role).toDouble(ok); };
    vehicle.id = value(m_names.id).toString();
    if (vehicle.id.isEmpty())
        vehicle.id = QStringLiteral("#%1").arg(row);
    vehicle.label = value(m_names.label).toString();
    bool okLat = false, okLon = false;
    const double lat = number(m_names.latitude, &okLat);
    const double lon = number(m_names.longitude, &okLon);
    if (okLat && okLon && std::isfinite(lat) && std::isfinite(lon))
        vehicle.position = WebMercator::project(lat, lon);
    const double homeLat = number(m_names.homeLatitude, &okLat);
    const double homeLon = number(m_names.homeLongitude, &okLon);
    if (okLat && okLon && std::isfinite(homeLat) && std::isfinite(homeLon))
        vehicle.home = WebMercator::project(homeLat, homeLon);
    bool okHeading = false;
    const double heading = number(m_names.heading, &okHeading);
    vehicle.heading = okHeading && std::isfinite(heading) ? heading : 0.0;
    vehicle.stale = value(m_names.stale).toBool();
    vehicle.color = client::vehicleColor(row);
    return vehicle;
}

} // namespace sortie::ui
