#include "MissionResume.h"

#include "FleetRoutes.h"
#include "Vehicle.h"
#include "VehicleFleet.h"

#include <QDateTime>

namespace sortie::resume {

using client::FleetRoute;
using client::FleetRouteState;
using client::FleetRoutes;

MissionResume::MissionResume(client::VehicleFleet *fleet, client::FleetRoutes *routes, QObject *parent)
    : QObject(parent)
    , m_fleet(fleet)
    , m_routes(routes)
{
    if (!routes)
        return;
    connect(routes, &QAbstractItemModel::dataChanged, this, &MissionResume::refresh);
    connect(routes, &QAbstractItemModel::rowsInserted, this, &MissionResume::refresh);
    connect(routes, &QAbstractItemModel::rowsRemoved, this, &MissionResume::refresh);
    connect(routes, &QAbstractItemModel::modelReset, this, &MissionResume::refresh);
}

vehicle::Vehicle *MissionResume::vehicle() const
{
    return m_vehicle;
}

void MissionResume::setVehicle(vehicle::Vehicle *vehicle)
{
    if (vehicle == m_vehicle)
        return;
    disconnect(m_telemetry);
    disconnect(m_photo);
    m_vehicle = vehicle;
    if (vehicle) {
        // Arming, landing and the position change the offer; refresh() signals only when it changed.
        m_telemetry = connect(vehicle, &vehicle::Vehicle::telemetryChanged, this, &MissionResume::refresh);
        m_photo = connect(vehicle, &vehicle::Vehicle::photoTaken, this, &MissionResume::refresh);
    }
    m_error.clear();
    m_notes.clear();
    emit vehicleChanged();
    emit resultChanged();
    refresh();
}

void MissionResume::refresh()
{
    // Each vehicle's photo count when its route went up: the photos of that route are the later ones.
    if (m_routes && m_fleet) {
        for (int row = 0; row < m_routes->count(); ++row) {
            const QModelIndex at = m_routes->index(row);
            const QDateTime uploaded = at.data(FleetRoutes::UploadedAtRole).toDateTime();
            if (!uploaded.isValid())
                continue;
            const QString id = at.data(FleetRoutes::VehicleIdRole).toString();
            Upload &upload = m_uploads[id];
            if (upload.at != uploaded) {
                const vehicle::Vehicle *v = m_fleet->vehicle(id);
                upload = {uploaded, v ? v->photoCount() : 0};
            }
        }
    }
    const Offer offer = currentOffer();
    if (offer == m_offer)
        return;
    m_offer = offer;
    emit offerChanged();
}

MissionResume::Offer MissionResume::currentOffer() const
{
    Offer offer;
    const vehicle::Vehicle *v = m_vehicle;
    const QString vehicleId = v ? v->fleetId() : QString();
    const FleetRoute *route = m_routes && v ? m_routes->onBoard(vehicleId) : nullptr;
    if (!route || !v->isConnected() || v->armed() || !v->position().isValid())
        return offer;
    // Stopped short (landed and no longer flying it), or still reported paused on the ground.
    const auto progress = route->stoppedShort ? route->stoppedShort : route->state == FleetRouteState::Flying ? route->progress : std::nullopt;
    if (!progress || progress->count <= 0 || progress->waypoint >= progress->count)
        return offer;
    const auto upload = m_uploads.find(vehicleId);
    offer.available = true;
    offer.reached = progress->waypoint - 1;
    offer.count = progress->count;
    offer.photos = upload != m_uploads.end() && upload->second.at == route->uploadedAt ? v->photoCount() - upload->second.photoCount : 0;
    const QString name = route->route.settings.name.isEmpty() ? tr("The route") : route->route.settings.name;
    offer.summary = offer.photos > 0 ? tr("%1 stopped flying to waypoint %2 of %3, after %n photo(s).", nullptr, offer.photos)
                                           .arg(name).arg(progress->waypoint).arg(progress->count)
                                     : tr("%1 stopped flying to waypoint %2 of %3.").arg(name).arg(progress->waypoint).arg(progress->count);
    return offer;
}

void MissionResume::fail(const QString &why)
{
    m_error = why;
    m_notes.clear();
    emit resultChanged();
}

bool MissionResume::resume(ResumeRequest::From from)
{
    const vehicle::Vehicle *v = m_vehicle;
    const QString vehicleId = v ? v->fleetId() : QString();
    const FleetRoute *route = m_routes && v ? m_routes->onBoard(vehicleId) : nullptr;
    if (!m_offer.available || !v || !route) {
        fail(tr("There is nothing to resume: no vehicle stands with a route flown part of the way."));
        return false;
    }
    ResumeRequest request;
    request.from = from;
    request.takeoff = {v->position().latitude(), v->position().longitude()};
    if (from == ResumeRequest::From::LastPhoto) {
        if (m_offer.photos <= 0) {
            fail(tr("The vehicle took no photo on this route."));
            return false;
        }
        request.lastPhoto = {v->lastPhoto().latitude, v->lastPhoto().longitude};
    } else {
        const std::vector<vehicle::MissionItem> &items = v->mission();
        for (int i = 0; i < m_offer.reached && size_t(i) < items.size(); ++i)
            request.reached.push_back({items[size_t(i)].latitude, items[size_t(i)].longitude});
        if (request.reached.empty()) {
            fail(tr("The vehicle reached no waypoint of this route."));
            return false;
        }
    }
    auto plan = resumeRoute(route->route, request);
    if (!plan) {
        fail(plan.error().message);
        return false;
    }
    m_error.clear();
    m_notes = plan->notes;
    emit resultChanged();
    if (m_open)
        m_open(std::move(plan->route), tr("Resume the mission"), vehicleId);
    emit opened();
    return true;
}

} // namespace sortie::resume
