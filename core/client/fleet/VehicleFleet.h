#pragma once

#include "CommandLog.h"
#include "CommandPolicy.h"
#include "Vehicle.h"
#include "VehicleGroup.h"

#include <QAbstractListModel>
#include <QPointer>

#include <memory>
#include <set>
#include <vector>

namespace sortie::hci {
class HciClient;
}
namespace sortie::terrain {
class ElevationService;
}
namespace sortie::vehicle {
struct VciFenceBuilder;
}
namespace sortie::tls {
class CertificateStore;
}

namespace sortie::client {

// Every vehicle the operator can see, whichever protocol reaches it: the server's vehicles over
// HCI (found when the session becomes ready) and vehicles connected directly over VCI. Any of them
// can take a route (MissionUploader); the fleet is the upload's vehicle chooser. One row per
// vehicle with what the map and the list show (position and heading in degrees for the map layer,
// protocol and link state); the Vehicle itself (instruments, history, commands) is `vehicle`.
// Rows change at most at the vehicles' notify rate (100 ms), never per telemetry message.
class VehicleFleet : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY countChanged)
    Q_PROPERTY(QString commandResult READ commandResult NOTIFY commandResultChanged)
    Q_PROPERTY(QString message READ message NOTIFY messageChanged)
    // Every command and upload sent to the fleet's vehicles, with its result.
    Q_PROPERTY(sortie::vehicle::CommandLog *commandLog READ commandLog CONSTANT)
    // The rules the command bar follows: what asks first, the take-off altitude, mode names.
    Q_PROPERTY(sortie::client::CommandPolicy *commands READ commands CONSTANT)
    // The vehicles chosen to be commanded together (their rows' `chosen`), and the group commands.
    Q_PROPERTY(sortie::client::VehicleGroup *group READ group CONSTANT)

public:
    enum Roles {
        VehicleIdRole = Qt::UserRole + 1, NameRole, ProtocolRole, LinkStateRole, StaleRole,
        LatitudeRole, LongitudeRole, HeadingRole, HomeLatitudeRole, HomeLongitudeRole,
        AltitudeAglRole, GroundSpeedRole, ModeRole, ArmedRole, BatteryRole, VehicleRole, ChosenRole,
    };

    // `elevation` (not owned, may be nullptr) gives VCI vehicles the ground under the routes they take.
    explicit VehicleFleet(hci::HciClient *client, terrain::ElevationService *elevation = nullptr, QObject *parent = nullptr);
    ~VehicleFleet() override;

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

    int count() const { return int(m_entries.size()); }
    QString commandResult() const { return m_commandResult; }
    QString message() const { return m_message; }
    Q_INVOKABLE sortie::vehicle::Vehicle *vehicleAt(int row) const;
    // The vehicle whose `vehicleId` role is `id` ("HCI:7", "VCI:vci-1"), or nullptr.
    Q_INVOKABLE sortie::vehicle::Vehicle *vehicle(const QString &id) const;
    vehicle::CommandLog *commandLog() { return &m_commandLog; }
    CommandPolicy *commands() { return &m_commands; }
    VehicleGroup *group() { return &m_group; }
    // The ground VCI routes are planned over (nullptr: none).
    terrain::ElevationService *elevation() const;
    // What makes the fence of a route going up to a VCI vehicle (airspace::vciFenceFor), for the VCI
    // vehicles added from now on; without it, a route that asks for a fence is refused.
    void setFenceBuilder(vehicle::VciFenceBuilder builder);
    // Where vci+tls:// vehicles' certificates are pinned and remembered (not owned; the login's store,
    // so one settings file holds them all), for the VCI vehicles added from now on.
    void setCertificateStore(tls::CertificateStore *store) { m_certificates = store; }

    // Connects a vehicle over VCI: tcp://host:port, vci+tls://host:port[?sha256=PIN] or serial:///dev/ttyX?baud=57600.
    Q_INVOKABLE bool addVciVehicle(const QString &endpoint);
    // Click-and-go: flies the vehicle to a point at its present altitude above ground (20 m when
    // unknown), 5 m/s. The result comes as commandResult.
    Q_INVOKABLE void goTo(int row, double latitude, double longitude);

signals:
    void countChanged();
    void commandResultChanged();
    void messageChanged();

private:
    struct Entry
    {
        std::unique_ptr<vehicle::VehicleLink> link;
        std::unique_ptr<vehicle::Vehicle> vehicle;
    };
    void add(std::unique_ptr<vehicle::VehicleLink> link);
    // Removes the HCI vehicles whose server object id is not in `keep`.
    void dropHciVehicles(const std::set<int> &keep = {});
    void discoverHciVehicles();
    void rowChanged(const vehicle::Vehicle *vehicle);
    void setCommandResult(const QString &text);

    QPointer<hci::HciClient> m_client;
    QPointer<terrain::ElevationService> m_elevation;
    std::unique_ptr<vehicle::VciFenceBuilder> m_fenceBuilder; // null: none
    tls::CertificateStore *m_certificates = nullptr;
    vehicle::CommandLog m_commandLog; // before the vehicles, which write to it
    CommandPolicy m_commands;
    VehicleGroup m_group{this, &m_commands};
    std::vector<Entry> m_entries;
    QString m_commandResult;
    QString m_message;
};

} // namespace sortie::client
