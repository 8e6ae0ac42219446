#pragma once

#include "SimLockTable.h"
#include "SimObjectStore.h"
#include "SimPower.h"
#include "SimRoutePasses.h"
#include "SimTraffic.h"
#include "SimUsers.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <memory>
#include <vector>

namespace com::ugcs::ucs::proto {
class CommandDefinition;
class TelemetryEvent;
} // namespace com::ugcs::ucs::proto

namespace sortie::sim {

class SimTerrain;
class SimVehicle;

// Everything the simulated UgCS server serves, independent of any connection: users, the object
// store (optionally persisted to a JSON file), locks, and the vehicles, which it flies and whose
// telemetry it publishes at a fixed rate.
class SimWorld : public QObject
{
    Q_OBJECT

public:
    struct Config
    {
        QList<SimUser> users;         // empty: admin/admin
        int vehicles = 3;             // EMU-101, EMU-102, EMU-103, ...
        double telemetryRateHz = 10;
        double groundElevation = 10;  // metres AMSL of the ground around Riga, away from the built-in hills
        QString demPath;              // SRTM .hgt tile or folder for the ground; empty: built-in terrain
        QString storePath;            // empty: in memory only
        int maxSessions = 0;          // licence limit on logged-in sessions; 0: none
        bool demoMission = true;
        bool mannedTraffic = true;    // the three aircraft through the demo area; false: an empty sky
        // What flying costs the vehicles and what their batteries hold (their speeds and rates too).
        endurance::EnergyProfile energy = simEnergyProfile();
    };

    explicit SimWorld(QObject *parent = nullptr);
    explicit SimWorld(Config config, QObject *parent = nullptr);
    ~SimWorld() override;

    // Loads the store file (if configured), adds the demo content and starts flying. Idempotent.
    bool start(QString *error = nullptr);
    bool isStarted() const { return m_started; }

    const Config &config() const { return m_config; }
    SimObjectStore &store() { return m_store; }
    SimLockTable &locks() { return m_locks; }
    // The RoutePass of every vehicle flying an uploaded route (kept in the store).
    SimRoutePasses &routePasses() { return m_routePasses; }
    const SimUsers &users() const { return m_users; }
    double groundElevation() const { return m_config.groundElevation; }
    // The ground everywhere (GetElevationProfile, route processing, telemetry's AGL).
    const SimTerrain &terrain() const { return *m_terrain; }
    // The manned aircraft flying through the demo area (ADS-B: the HCI list, sortie-sim --sbs-port).
    const SimTraffic &traffic() const { return m_traffic; }
    static qint64 now();

    const std::vector<std::unique_ptr<SimVehicle>> &vehicles() const { return m_vehicles; }
    SimVehicle *vehicle(int id) const;
    std::vector<pb::CommandDefinition> commandDefinitions() const;

    void setTelemetryRate(double hz);
    // Flushes the store to its file now (it is also saved shortly after every change).
    bool saveStore(QString *error = nullptr);

signals:
    void telemetry(const pb::TelemetryEvent &event);
    // A vehicle's available commands changed.
    void commandsChanged(int vehicleId);

private:
    void tick();

    Config m_config;
    SimUsers m_users;
    SimObjectStore m_store;
    SimLockTable m_locks;
    SimRoutePasses m_routePasses{m_store};
    std::unique_ptr<SimTerrain> m_terrain;
    SimTraffic m_traffic;
    std::vector<std::unique_ptr<SimVehicle>> m_vehicles;
    QTimer m_ticker;
    QTimer m_saveTimer;
    QElapsedTimer m_clock;
    qint64 m_lastTickNs = 0;
    bool m_started = false;
};

} // namespace sortie::sim
