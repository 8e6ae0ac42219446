#pragma once

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>

class QSettings;

// The properties' types, complete for moc alone: the header itself forward-declares them.
Q_MOC_INCLUDE("Airspace.h")
Q_MOC_INCLUDE("AutosaveRecovery.h")
Q_MOC_INCLUDE("ComparisonController.h")
Q_MOC_INCLUDE("ConnectionController.h")
Q_MOC_INCLUDE("ElevationService.h")
Q_MOC_INCLUDE("FleetRoutes.h")
Q_MOC_INCLUDE("MissionController.h")
Q_MOC_INCLUDE("OfflineMaps.h")
Q_MOC_INCLUDE("ProximityMonitor.h")
Q_MOC_INCLUDE("RecordingSettings.h")
Q_MOC_INCLUDE("ReplayController.h")
Q_MOC_INCLUDE("PhotoSurvey.h")
Q_MOC_INCLUDE("MissionResume.h")
Q_MOC_INCLUDE("RouteDeconfliction.h")
Q_MOC_INCLUDE("RouteEndurance.h")
Q_MOC_INCLUDE("ServerHistoryRequest.h")
Q_MOC_INCLUDE("Traffic.h")
Q_MOC_INCLUDE("VehicleFleet.h")
Q_MOC_INCLUDE("VehicleVideo.h")
Q_MOC_INCLUDE("PreflightChecklists.h")
Q_MOC_INCLUDE("GamepadCommands.h")
Q_MOC_INCLUDE("ZoneAlertMonitor.h")
Q_MOC_INCLUDE("ZoneFeed.h")
Q_MOC_INCLUDE("ZoneSharing.h")

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

namespace sortie::coverage {
class PhotoSurvey;
} // namespace sortie::coverage

namespace sortie::resume {
class MissionResume;
} // namespace sortie::resume

namespace sortie::endurance {
class RouteEndurance;
} // namespace sortie::endurance

namespace sortie::airspace {
class Airspace;
class ServerZones;
class ZoneFeed;
class ZoneSharing;
} // namespace sortie::airspace

namespace sortie::traffic {
class Traffic;
} // namespace sortie::traffic

namespace sortie::video {
class VehicleVideo;
} // namespace sortie::video
namespace sortie::preflight {
class PreflightChecklists;
} // namespace sortie::preflight
namespace sortie::gamepad {
class GamepadCommands;
} // namespace sortie::gamepad
namespace sortie::maptiles {
class OfflineMaps;
} // namespace sortie::maptiles

namespace sortie::airspace {
class AirspaceToVehicles;
class UploadedFenceAlerts;
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
//
// QML is handed the graph once (Main.qml's `graph`): each service a view uses is a typed constant
// property here, so a new service is a member, a line in the constructor, a property and the view
// that reads it (docs/architecture.md, "How to add a service").
class ClientGraph : public QObject
{
    Q_OBJECT
    // The services the views use. Constant: made once with the graph, never replaced; the ones marked
    // "nullable" are null in a graph built without them (Options), and stay so.
    Q_PROPERTY(sortie::client::ConnectionController *connection READ connectionForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::client::MissionController *missions READ missionsForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::terrain::ElevationService *elevation READ elevationForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::client::VehicleFleet *fleet READ fleetForQml CONSTANT FINAL)               // nullable: vehicles
    Q_PROPERTY(sortie::client::FleetRoutes *fleetRoutes READ fleetRoutesForQml CONSTANT FINAL)    // nullable: vehicles
    Q_PROPERTY(sortie::client::AutosaveRecovery *recovery READ recoveryForQml CONSTANT FINAL)     // nullable: autosaveDirectory
    Q_PROPERTY(sortie::endurance::RouteEndurance *endurance READ enduranceForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::airspace::Airspace *airspace READ airspaceForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::airspace::ZoneSharing *zoneSharing READ zoneSharingForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::airspace::ZoneFeed *zoneFeed READ zoneFeedForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::traffic::Traffic *traffic READ trafficForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::video::VehicleVideo *video READ videoForQml CONSTANT FINAL)                           // nullable: vehicles
    Q_PROPERTY(sortie::preflight::PreflightChecklists *preflight READ preflightForQml CONSTANT FINAL)        // nullable: vehicles
    Q_PROPERTY(sortie::gamepad::GamepadCommands *gamepads READ gamepadsForQml CONSTANT FINAL)                // nullable: vehicles
    Q_PROPERTY(sortie::maptiles::OfflineMaps *offlineMaps READ offlineMapsForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::deconfliction::ProximityMonitor *proximity READ proximityForQml CONSTANT FINAL)        // nullable: vehicles
    Q_PROPERTY(sortie::airspace::ZoneAlertMonitor *zoneAlerts READ zoneAlertsForQml CONSTANT FINAL)           // nullable: vehicles
    Q_PROPERTY(sortie::deconfliction::RouteDeconfliction *deconfliction READ deconflictionForQml CONSTANT FINAL) // nullable: vehicles
    Q_PROPERTY(sortie::flightlog::RecordingSettings *recordingSettings READ recordingSettingsForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::flightlog::ReplayController *replay READ replayForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::flightlog::ComparisonController *comparison READ comparisonForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::flightlog::ServerHistoryRequest *serverHistory READ serverHistoryForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::coverage::PhotoSurvey *photos READ photosForQml CONSTANT FINAL)
    Q_PROPERTY(sortie::resume::MissionResume *resume READ resumeForQml CONSTANT FINAL)                       // nullable: vehicles

public:
    struct Options
    {
        QString demFolder;          // a DEM file or folder (core/raster); empty: the setting terrain/demFolder (none when unset)
        QString autosaveDirectory;  // empty: no autosave and no recovery
        QString flightLogDirectory; // empty: the recorder exists (for its settings) but records nothing
        bool vehicles = true;       // false: no fleet (a fault test of the connection alone)
        QString sbsAddress;         // an ADS-B receiver's SBS-1 feed; empty: the setting traffic/sbsAddress
        QString zoneFeedDirectory;  // where published zone files fetched from a URL are kept; empty: none can be
        QString checklistDirectory; // the operator's pre-flight checklists (<vehicle type>.json, default.json); empty: Sortie's own
    };

    // `storage` (not owned, required) holds the operator's settings: terrain folder and source order,
    // the recording limits.
    ClientGraph(QSettings *storage, Options options, QObject *parent = nullptr);
    ~ClientGraph() override;

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
    airspace::ZoneFeed &zoneFeed() { return *m_zoneFeed; }
    // Manned traffic: the picture, the receiver's feed and the server's ADS-B list.
    traffic::Traffic &traffic() { return *m_traffic; }
    // Each vehicle's live video; null in a graph without vehicles.
    video::VehicleVideo *video() const { return m_video.get(); }
    // Each vehicle's pre-flight checklist, the gate on its Arm, take-off and Auto; null without vehicles.
    preflight::PreflightChecklists *preflight() const { return m_preflight.get(); }
    // The gamepads' buttons as commands (SDL started only while enabled); null without vehicles.
    gamepad::GamepadCommands *gamepads() const { return m_gamepads.get(); }
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
    // The replayed flight's photos: placed on its log, their coverage judged, their copies written.
    coverage::PhotoSurvey &photos() { return *m_photos; }
    // A mission a vehicle stopped half-way, offered to be finished (nullptr without vehicles).
    resume::MissionResume *resume() const { return m_resume.get(); }
    // The terrain reads this DEM file or folder from now on (empty: none), in the source order the
    // settings give: the operator chose another in the map source dialog.
    void useDem(const QString &path);

    // Why the recorder did not start; empty when it records or was not asked to.
    QString recorderError() const { return m_recorderError; }

    // What is wired to what, read back from the objects themselves (not from what the constructor
    // meant to do): one line per service. Logged at start; a test compares a fixture's with the
    // program's.
    QStringList wiring() const;

private:
    // The properties' getters: QML reads pointers, C++ takes the references above.
    ConnectionController *connectionForQml() const { return m_connection.get(); }
    MissionController *missionsForQml() const { return m_missions.get(); }
    terrain::ElevationService *elevationForQml() const;
    VehicleFleet *fleetForQml() const { return m_fleet.get(); }
    FleetRoutes *fleetRoutesForQml() const { return m_fleetRoutes.get(); }
    AutosaveRecovery *recoveryForQml() const { return m_recovery.get(); }
    endurance::RouteEndurance *enduranceForQml() const { return m_endurance.get(); }
    airspace::Airspace *airspaceForQml() const { return m_airspace.get(); }
    airspace::ZoneSharing *zoneSharingForQml() const { return m_zoneSharing.get(); }
    airspace::ZoneFeed *zoneFeedForQml() const { return m_zoneFeed.get(); }
    traffic::Traffic *trafficForQml() const { return m_traffic.get(); }
    video::VehicleVideo *videoForQml() const { return m_video.get(); }
    preflight::PreflightChecklists *preflightForQml() const { return m_preflight.get(); }
    gamepad::GamepadCommands *gamepadsForQml() const { return m_gamepads.get(); }
    maptiles::OfflineMaps *offlineMapsForQml() const { return m_offlineMaps.get(); }
    deconfliction::ProximityMonitor *proximityForQml() const { return m_proximity.get(); }
    airspace::ZoneAlertMonitor *zoneAlertsForQml() const { return m_zoneAlerts.get(); }
    deconfliction::RouteDeconfliction *deconflictionForQml() const { return m_deconfliction.get(); }
    flightlog::RecordingSettings *recordingSettingsForQml() const { return m_recordingSettings.get(); }
    flightlog::ReplayController *replayForQml() const { return m_replay.get(); }
    flightlog::ComparisonController *comparisonForQml() const { return m_comparison.get(); }
    flightlog::ServerHistoryRequest *serverHistoryForQml() const { return m_serverHistory.get(); }
    coverage::PhotoSurvey *photosForQml() const { return m_photos.get(); }
    resume::MissionResume *resumeForQml() const { return m_resume.get(); }

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
    std::unique_ptr<airspace::ZoneFeed> m_zoneFeed;
    std::unique_ptr<traffic::Traffic> m_traffic;
    std::unique_ptr<video::VehicleVideo> m_video;
    std::unique_ptr<preflight::PreflightChecklists> m_preflight;
    std::unique_ptr<gamepad::GamepadCommands> m_gamepads;
    std::unique_ptr<maptiles::OfflineMaps> m_offlineMaps;
    std::unique_ptr<FleetRoutes> m_fleetRoutes;
    std::unique_ptr<deconfliction::RouteDeconfliction> m_deconfliction;
    std::unique_ptr<deconfliction::ProximityMonitor> m_proximity;
    std::unique_ptr<airspace::ZoneAlertMonitor> m_zoneAlerts;
    std::unique_ptr<airspace::UploadedFenceAlerts> m_uploadedFenceAlerts; // with the zone alerts
    std::unique_ptr<airspace::AirspaceToVehicles> m_airspaceToVehicles;
    std::unique_ptr<AutosaveRecovery> m_recovery;
    std::unique_ptr<RouteAutosave> m_autosave;
    std::unique_ptr<flightlog::FlightRecorder> m_recorder;
    std::unique_ptr<flightlog::RecordingSettings> m_recordingSettings;
    std::unique_ptr<flightlog::FleetRecording> m_fleetRecording;
    std::unique_ptr<flightlog::ReplayController> m_replay;
    std::unique_ptr<flightlog::ComparisonController> m_comparison;
    std::unique_ptr<flightlog::ServerHistoryRequest> m_serverHistory;
    std::unique_ptr<coverage::PhotoSurvey> m_photos;
    std::unique_ptr<resume::MissionResume> m_resume;
    QSettings *m_storage;
    QString m_recorderError;
};

} // namespace sortie::client
