#pragma once

#include "VehicleMark.h"

#include <QHash>
#include <QString>

class QAbstractItemModel;

namespace sortie::ui {

// The role names a vehicle model is read by: any model with these roles fits.
struct VehicleRoleNames
{
    QString id = QStringLiteral("vehicleId");
    QString latitude = QStringLiteral("latitude");
    QString longitude = QStringLiteral("longitude");
    QString heading = QStringLiteral("heading");
    QString label = QStringLiteral("name");
    QString homeLatitude = QStringLiteral("homeLatitude");
    QString homeLongitude = QStringLiteral("homeLongitude");
    QString stale = QStringLiteral("stale");
};

// Reads a vehicle list model's rows into VehicleMarks. A row without a usable position or home
// (a missing role, not a number, not finite) has none; a row without an id is keyed by its row.
class VehicleModelReader
{
public:
    // Looks the role names up in the model (again after its roles may have changed).
    void resolve(const QAbstractItemModel *model, const VehicleRoleNames &names);
    VehicleMark read(const QAbstractItemModel &model, int row) const;

private:
    VehicleRoleNames m_names;
    QHash<QString, int> m_roles; // role name -> role
};

} // namespace sortie::ui
