#pragma once

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>

class QSettings;

namespace sortie::hci {
class HciClient;
class HciSession;
} // namespace sortie::hci

namespace sortie::terrain {
class ElevationService;
class ElevationSetup;
} // namespace sortie::terrain

namespace sortie::flightlog {
class ComparisonController;
class FleetRecording;
class FlightRecorder;
class RecordingSettings;
class ReplayController;
class ServerHistoryRequest;
} // namespace sortie::flightlog

namespace sortie::endurance {
class RouteEndurance;
} // namespace sortie::endurance

namespace sortie::airspace {
class Airspace;
class ServerZones;
class ZoneSharing;
} // namespace sortie::airspace

namespace sortie::traffic {
class Traffic;
} // namespace sortie::traffic
namespace sortie::maptiles {
class OfflineMaps;
} // namespace sortie::maptiles

namespace sortie::airspace {
class ZoneAlertMonitor;
} // namespace sortie::airspace

namespace sortie::deconfliction {
class ProximityMonitor;
class RouteDeconfliction;
} // namespace sortie::deconfliction

namespace sortie::client {

class AutosaveRecovery;
class ConnectionController;
class FleetRoutes;
class MissionController;
class RouteAutosave;
class VehicleFleet;

// The client's object graph, built and wired in one place: the HCI session and the controllers the
// views bind to, the terrain sources and what uses them (the fleet's VCI planning, the route's
// validation, the editor's height conversions), the open route's endurance (its rule), manned traffic, autosave and recovery, the flight recorder and
// replay. The program (app/sortie) and every test fixture build it, so a test runs the program's own
// wiring; a fixture changes what it must (folders, no vehicles) through Options, never by hand.
class ClientGraph
{
public:
    struct Options
    {
        QString demFolder;          // a DEM file or folder (core/raster); empty: the setting terrain/demFolder (none when unset)
        QString autosaveDirectory;  // empty: no autosave and no recovery
        QString flightLogDirectory; // empty: the recorder exists (for its settings) but records nothing
        bool vehicles = true;       // false: no fleet (a fault test of the connection alone)
        QString sbsAddress;         // an ADS-B receiver's SBS-1 feed; empty: the setting traffic/sbsAddress
    };

    // `storage` (not owned, required) holds the operator's settings: terrain folder and source order,
    // the recording limits.
    ClientGraph(QSettings *storage, Options options);
    ~ClientGraph();
    ClientGraph(const ClientGraph &) = delete;
    ClientGraph &operator=(const ClientGraph &) = delete;

    hci::HciSession &session() { return *m_session; }
    hci::HciClient &hciClient() { return *m_hciClient; }
    ConnectionController &connection() { return *m_connection; }
    MissionController &missions() { return *m_missions; }
    terrain::ElevationSetup &terrain() { return *m_elevation; }
    terrain::ElevationService *elevation();
    VehicleFleet *fleet() { return m_fleet.get(); }               // nullptr without vehicles
    FleetRoutes *fleetRoutes() { return m_fleetRoutes.get(); }    // every vehicle's route; nullptr without vehicles
    AutosaveRecovery *recovery() { return m_recovery.get(); }     // nullptr without an autosave folder
    RouteAutosave *autosave() { return m_autosave.get(); }        // nullptr without an autosave folder
    flightlog::FlightRecorder &recorder() { return *m_recorder; }
    flightlog::RecordingSettings &recordingSettings() { return *m_recordingSettings; }
    endurance::RouteEndurance &endurance() { return *m_endurance; }
    // The zones (drawn, the server's, files, the route's fence) and the airspace rule on the route.
    airspace::Airspace &airspace() { return *m_airspace; }
    // The server's no-fly zones where the maps look, fed into the airspace.
    airspace::ServerZones &serverZones() { return *m_serverZones; }
    // Drawn zones sent to the server; the server's custom zones edited on the map and deleted.
    airspace::ZoneSharing &zoneSharing() { return *m_zoneSharing; }
    // Manned traffic: the picture, the receiver's feed and the server's ADS-B list.
    traffic::Traffic &traffic() { return *m_traffic; }
    // Maps taken offline: the area, the download into an MBTiles pack, cache-only (docs/offline-maps.md).
    maptiles::OfflineMaps &offlineMaps() { return *m_offlineMaps; }
    // In-flight closest-approach alerts between the fleet's vehicles and against the traffic;
    // nullptr without vehicles.
    deconfliction::ProximityMonitor *proximity() { return m_proximity.get(); }
    // In-flight zone alerts: each vehicle against the airspace and the route fence uploaded with
    // its mission; nullptr without vehicles.
    airspace::ZoneAlertMonitor *zoneAlerts() { return m_zoneAlerts.get(); }
    // The open route's 4D conflicts with the fleet's other routes (a rule on its analyzer);
    // nullptr without vehicles.
    deconfliction::RouteDeconfliction *deconfliction() { return m_deconfliction.get(); }
    flightlog::ReplayController &replay() { return *m_replay; }
    flightlog::ComparisonController &comparison() { return *m_comparison; }
    flightlog::ServerHistoryRequest &serverHistory() { return *m_serverHistory; }
    // Why the recorder did not start; empty when it records or was not asked to.
    QString recorderError() const { return m_recorderError; }

    // What is wired to what, read back from the objects themselves (not from what the constructor
    // meant to do): one line per service. Logged at start; a test compares a fixture's with the
    // program's.
    QStringList wiring() const;

private:
    std::unique_ptr<hci::HciSession> m_session;
    std::unique_ptr<hci::HciClient> m_hciClient;
    std::unique_ptr<ConnectionController> m_connection;
    std::unique_ptr<MissionController> m_missions;
    std::unique_ptr<terrain::ElevationSetup> m_elevation;
    std::unique_ptr<endurance::RouteEndurance> m_endurance;
    std::unique_ptr<airspace::Airspace> m_airspace;
    std::unique_ptr<VehicleFleet> m_fleet;
    std::unique_ptr<airspace::ServerZones> m_serverZones;
    std::unique_ptr<airspace::ZoneSharing> m_zoneSharing;
    std::unique_ptr<traffic::Traffic> m_traffic;
    std::unique_ptr<maptiles::OfflineMaps> m_offlineMaps;
    std::unique_ptr<FleetRoutes> m_fleetRoutes;
    std::unique_ptr<deconfliction::RouteDeconfliction> m_deconfliction;
    std::unique_ptr<deconfliction::ProximityMonitor> m_proximity;
    std::unique_ptr<airspace::ZoneAlertMonitor> m_zoneAlerts;
    std::unique_ptr<AutosaveRecovery> m_recovery;
    std::unique_ptr<RouteAutosave> m_autosave;
    std::unique_ptr<flightlog::FlightRecorder> m_recorder;
    std::unique_ptr<flightlog::RecordingSettings> m_recordingSettings;
    std::unique_ptr<flightlog::FleetRecording> m_fleetRecording;
    std::unique_ptr<flightlog::ReplayController> m_replay;
    std::unique_ptr<flightlog::ComparisonController> m_comparison;
    std::unique_ptr<flightlog::ServerHistoryRequest> m_serverHistory;
    QString m_recorderError;
};

} // namespace sortie::client
