#include "UploadedFenceAlerts.h"

#include "MissionUploader.h"
#include "Vehicle.h"
#include "ZoneAlertMonitor.h"

#include <QCoreApplication>

namespace sortie::airspace {

UploadedFenceAlerts::UploadedFenceAlerts(client::MissionUploader *uploader, ZoneAlertMonitor *alerts)
{
    Q_ASSERT(uploader && alerts);
    m_uploads = QObject::connect(uploader, &client::MissionUploader::uploaded, alerts, [uploader, alerts](vehicle::Vehicle *v) {
        const mission::Route &route = uploader->route();
        alerts->setVehicleZones(v->id(), zonesOfFence(route.fence, QCoreApplication::translate("UploadedFenceAlerts", "route fence"),
                                                      ZoneSource::VehicleFence, route.settings.name));
    });
}

UploadedFenceAlerts::~UploadedFenceAlerts()
{
    QObject::disconnect(m_uploads);
}

} // namespace sortie::airspace
