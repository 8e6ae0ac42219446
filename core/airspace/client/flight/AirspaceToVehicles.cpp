#include "AirspaceToVehicles.h"

#include "Airspace.h"
#include "MissionUploader.h"
#include "VciFenceBuilder.h"
#include "ZoneAlertMonitor.h"

namespace sortie::airspace {

AirspaceToVehicles::AirspaceToVehicles(Airspace *airspace, client::MissionUploader *uploader, ZoneAlertMonitor *alerts)
    : m_airspace(airspace)
    , m_uploader(uploader)
    , m_alerts(alerts)
{
    Q_ASSERT(airspace && uploader);
    share();
    m_changes = QObject::connect(airspace, &Airspace::changed, uploader, [this] { share(); });
}

AirspaceToVehicles::~AirspaceToVehicles()
{
    QObject::disconnect(m_changes);
}

void AirspaceToVehicles::share()
{
    if (m_alerts)
        m_alerts->setZones(m_airspace->zoneSet());
    std::vector<Zone> beyondRoute;
    for (int row = 0; row < m_airspace->count(); ++row)
        if (m_airspace->groupOf(row) != Airspace::Group::RouteFence)
            beyondRoute.push_back(m_airspace->zoneAt(row));
    vehicle::FenceSettings fence = m_uploader->fenceSettings();
    fence.zones = std::make_shared<const FenceZoneSet>(std::move(beyondRoute));
    m_uploader->setFenceSettings(std::move(fence));
}

} // namespace sortie::airspace
