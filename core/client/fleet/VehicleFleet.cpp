#include "VehicleFleet.h"
#include "LanguageChange.h"

#include <QtMath>

#include "HciClient.h"
#include "HciReply.h"
#include "HciSession.h"
#include "HciVehicleLink.h"
#include "Messages.pb.h"
#include "VciEndpoint.h"
#include "ElevationService.h"
#include "VciVehicleLink.h"

#include <QMetaEnum>

#include <set>

#include <cmath>
#include <numbers>

namespace sortie::client {

namespace pb = com::ugcs::ucs::proto;
using vehicle::Vehicle;
using vehicle::VehicleLink;

VehicleFleet::VehicleFleet(hci::HciClient *client, terrain::ElevationService *elevation, QObject *parent)
    : QAbstractListModel(parent)
    , m_client(client)
    , m_elevation(elevation)
{
    i18n::refreshOnLanguageChange(this);
    connect(client->session(), &hci::HciSession::ready, this, &VehicleFleet::discoverHciVehicles);
    connect(client->session(), &hci::HciSession::stateChanged, this, [this](hci::HciSession::State state) {
        if (state == hci::HciSession::State::Disconnected)
            dropHciVehicles();
    });
    connect(&m_group, &VehicleGroup::changed, this, [this] {
        if (count() > 0)
            emit dataChanged(index(0), index(count() - 1), {ChosenRole});
    });
}

terrain::ElevationService *VehicleFleet::elevation() const
{
    return m_elevation;
}

void VehicleFleet::setFenceBuilder(vehicle::VciFenceBuilder builder)
{
    m_fenceBuilder = std::make_unique<vehicle::VciFenceBuilder>(std::move(builder));
}

VehicleFleet::~VehicleFleet()
{
    // Vehicles first (they watch their links), then the links, with nothing reaching back here.
    for (Entry &entry : m_entries) {
        disconnect(entry.vehicle.get(), nullptr, this, nullptr);
        entry.vehicle.reset();
        entry.link.reset();
    }
}

int VehicleFleet::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QHash<int, QByteArray> VehicleFleet::roleNames() const
{
    return {{VehicleIdRole, "vehicleId"}, {NameRole, "name"}, {ProtocolRole, "protocol"}, {LinkStateRole, "linkState"},
            {StaleRole, "stale"}, {LatitudeRole, "latitude"}, {LongitudeRole, "longitude"}, {HeadingRole, "heading"},
            {HomeLatitudeRole, "homeLatitude"}, {HomeLongitudeRole, "homeLongitude"}, {AltitudeAglRole, "altitudeAgl"},
            {GroundSpeedRole, "groundSpeed"}, {ModeRole, "mode"}, {ArmedRole, "armed"}, {BatteryRole, "battery"},
            {VehicleRole, "vehicle"}, {ChosenRole, "chosen"}};
}

QVariant VehicleFleet::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const Vehicle &v = *m_entries[size_t(index.row())].vehicle;
    auto finite = [](double value) { return std::isfinite(value) ? QVariant(value) : QVariant(); };
    switch (role) {
    case VehicleIdRole: return v.fleetId();
    case NameRole:
    case Qt::DisplayRole: return v.name();
    case ProtocolRole: return v.protocol();
    case LinkStateRole: return QString::fromLatin1(QMetaEnum::fromType<VehicleLink::State>().valueToKey(int(v.linkState())));
    case StaleRole: return v.isStale() || !v.isConnected();
    case LatitudeRole: return v.position().isValid() ? QVariant(v.position().latitude()) : QVariant();
    case LongitudeRole: return v.position().isValid() ? QVariant(v.position().longitude()) : QVariant();
    case HeadingRole: return finite(v.heading());
    case HomeLatitudeRole: return v.home().isValid() ? QVariant(v.home().latitude()) : QVariant();
    case HomeLongitudeRole: return v.home().isValid() ? QVariant(v.home().longitude()) : QVariant();
    case AltitudeAglRole: return finite(v.altitudeAgl());
    case GroundSpeedRole: return finite(v.groundSpeed());
    case ModeRole: return v.mode();
    case ArmedRole: return v.armed();
    case BatteryRole: return finite(v.batteryRemaining());
    case VehicleRole: return QVariant::fromValue(static_cast<QObject *>(m_entries[size_t(index.row())].vehicle.get()));
    case ChosenRole: return m_group.contains(v.fleetId());
    default: return {};
    }
}

Vehicle *VehicleFleet::vehicleAt(int row) const
{
    return row >= 0 && row < count() ? m_entries[size_t(row)].vehicle.get() : nullptr;
}

Vehicle *VehicleFleet::vehicle(const QString &id) const
{
    for (const Entry &entry : m_entries) {
        if (entry.vehicle->fleetId() == id)
            return entry.vehicle.get();
    }
    return nullptr;
}

void VehicleFleet::add(std::unique_ptr<VehicleLink> link)
{
    // Parented, so that QML, which receives it from vehicleAt(), never takes it over and deletes it.
    auto vehicle = std::make_unique<Vehicle>(link.get(), this);
    Vehicle *raw = vehicle.get();
    raw->setCommandLog(&m_commandLog);
    connect(raw, &Vehicle::telemetryChanged, this, [this, raw] { rowChanged(raw); });
    connect(raw, &Vehicle::staleChanged, this, [this, raw] { rowChanged(raw); });
    connect(raw, &Vehicle::linkStateChanged, this, [this, raw] { rowChanged(raw); });
    connect(raw, &Vehicle::identityChanged, this, [this, raw] { rowChanged(raw); });
    connect(raw, &Vehicle::commandFinished, this, [this, raw](const QString &command, bool ok, const QString &message) {
        setCommandResult(ok ? tr("%1: %2 done.").arg(raw->name(), command)
                            : tr("%1: %2 failed: %3").arg(raw->name(), command, message));
    });
    beginInsertRows({}, count(), count());
    link->start();
    m_entries.push_back({std::move(link), std::move(vehicle)});
    endInsertRows();
    emit countChanged();
}

void VehicleFleet::rowChanged(const Vehicle *vehicle)
{
    for (size_t row = 0; row < m_entries.size(); ++row) {
        if (m_entries[row].vehicle.get() == vehicle) {
            emit dataChanged(index(int(row)), index(int(row)));
            return;
        }
    }
}

void VehicleFleet::discoverHciVehicles()
{
    if (!m_client)
        return;
    hci::HciReply *reply = m_client->listObjects(hci::HciObjectType::Vehicle);
    connect(reply, &hci::HciReply::finished, this, [this, reply] {
        if (!reply->isOk()) {
            m_message = tr("The server's vehicles could not be read: %1").arg(reply->error().message());
            emit messageChanged();
            return;
        }
        // After a reconnect the same vehicles come back: keep their Vehicle (its history, and the
        // pointers the views hold); drop only those the server no longer has, add the new ones.
        std::set<int> listed;
        for (const pb::DomainObjectWrapper &object : reply->response<pb::GetObjectListResponse>().objects())
            listed.insert(object.vehicle().id());
        dropHciVehicles(listed);
        std::set<int> present;
        for (const Entry &entry : m_entries) {
            if (const auto *link = qobject_cast<const vehicle::HciVehicleLink *>(entry.link.get()))
                present.insert(link->vehicleObjectId());
        }
        for (const pb::DomainObjectWrapper &object : reply->response<pb::GetObjectListResponse>().objects()) {
            if (!present.count(object.vehicle().id()))
                add(std::make_unique<vehicle::HciVehicleLink>(m_client, object.vehicle()));
        }
    });
}

void VehicleFleet::dropHciVehicles(const std::set<int> &keep)
{
    for (int row = count() - 1; row >= 0; --row) {
        const auto *link = qobject_cast<const vehicle::HciVehicleLink *>(m_entries[size_t(row)].link.get());
        if (!link || keep.count(link->vehicleObjectId()))
            continue;
        beginRemoveRows({}, row, row);
        Entry gone = std::move(m_entries[size_t(row)]);
        m_entries.erase(m_entries.begin() + row);
        endRemoveRows();
        disconnect(gone.vehicle.get(), nullptr, this, nullptr);
        gone.vehicle.reset();
        gone.link.reset();
    }
    emit countChanged();
}

bool VehicleFleet::addVciVehicle(const QString &text)
{
    QString error;
    const auto endpoint = vci::VciEndpoint::parse(text, &error);
    if (!endpoint) {
        m_message = tr("Not a VCI address: %1").arg(error);
        emit messageChanged();
        return false;
    }
    auto link = std::make_unique<vehicle::VciVehicleLink>(*endpoint, m_elevation.data());
    if (m_fenceBuilder)
        link->setFenceBuilder(*m_fenceBuilder);
    link->transport()->setCertificateStore(m_certificates);
    add(std::move(link));
    return true;
}

void VehicleFleet::goTo(int row, double latitude, double longitude)
{
    Vehicle *v = vehicleAt(row);
    if (!v || !v->link())
        return;
    const double agl = v->altitudeAgl();
    const double altitude = std::isfinite(agl) && agl > 2 ? agl : 20.0;
    const QString name = v->name();
    auto logged = m_commandLog.track(name, tr("go to %1, %2 at %3 m").arg(latitude, 0, 'f', 6).arg(longitude, 0, 'f', 6).arg(altitude, 0, 'f', 0));
    v->link()->goTo(latitude, longitude, altitude, 5.0, [this, name, logged](const vehicle::CommandResult &result) {
        logged(result);
        setCommandResult(result.ok ? tr("%1: flying to the clicked point.").arg(name)
                                   : tr("%1: go-to failed: %2").arg(name, result.message));
    });
}

void VehicleFleet::setCommandResult(const QString &text)
{
    m_commandResult = text;
    emit commandResultChanged();
}

} // namespace sortie::client
