#include "ClientGraph.h"

#include "Airspace.h"
#include "AirspaceRule.h"
#include "AirspaceToVehicles.h"
#include "AutosaveRecovery.h"
#include "ComparisonController.h"
#include "ConnectionController.h"
#include "DemOpener.h"
#include "ElevationSetup.h"
#include "FleetRoutes.h"
#include "EnduranceRule.h"
#include "FleetRecording.h"
#include "FlightRecorder.h"
#include "HciClient.h"
#include "HciSession.h"
#include "MissionController.h"
#include "FleetConflictRule.h"
#include "ProximityMonitor.h"
#include "RouteDeconfliction.h"
#include "RecordingSettings.h"
#include "MissionResume.h"
#include "PhotoSurvey.h"
#include "ReplayController.h"
#include "RouteAnalyzer.h"
#include "RouteAutosave.h"
#include "RouteDocument.h"
#include "RouteEditor.h"
#include "RouteEndurance.h"
#include "RouteModel.h"
#include "SbsFeed.h"
#include "ServerHistoryRequest.h"
#include "Traffic.h"
#include "VehicleVideo.h"
#include "PreflightChecklists.h"
#include "GamepadCommands.h"
#include "UploadedFenceAlerts.h"
#include "OfflineMaps.h"
#include "VciFenceBuilder.h"
#include "VehicleFleet.h"
#include "ServerZones.h"
#include "ZoneFeed.h"
#include "ZoneSharing.h"
#include "ZoneAlertMonitor.h"

#include <QLoggingCategory>
#include <QSettings>

#include <algorithm>

Q_LOGGING_CATEGORY(lcClientGraph, "sortie.client.graph")

namespace sortie::client {

namespace {

// How much the recorder buffers before it writes: half a second of telemetry.
constexpr int kRecorderFlushMs = 500;

QString yesNo(bool on, const char *yes, const char *no)
{
    return QString::fromLatin1(on ? yes : no);
}

} // namespace

ClientGraph::ClientGraph(QSettings *storage, Options options, QObject *parent)
    : QObject(parent)
    , m_session(std::make_unique<hci::HciSession>())
    , m_hciClient(std::make_unique<hci::HciClient>(m_session.get()))
    , m_connection(std::make_unique<ConnectionController>(m_session.get(), storage)) // its certificates and answers are remembered there
    , m_missions(std::make_unique<MissionController>(m_hciClient.get()))
    , m_elevation(std::make_unique<terrain::ElevationSetup>(m_session.get()))
    , m_storage(storage)
{
    Q_ASSERT(storage);
    // Terrain: a local DEM (the option, else the setting; any raster GDAL reads) and the server, in
    // the order the settings give.
    m_elevation->setDemOpener(raster::openDem);
    useDem(options.demFolder.isEmpty() ? storage->value(QStringLiteral("terrain/demFolder")).toString() : options.demFolder);
    RouteDocument *document = m_missions->document();
    document->analyzer()->addRule(m_elevation->rule());
    terrain::ElevationService *ground = m_elevation->service();
    document->editor()->setGroundLookup([ground](const mission::GeoPoint &p) { return ground->groundAt(p); });
    // The open route's endurance: the operator's energy profile (remembered in the settings) and its rule.
    m_endurance = std::make_unique<endurance::RouteEndurance>(storage, document->analyzer(), document->model());
    // Airspace: its rule on the route's analyzer; the zones drawn here kept beside the autosaves.
    m_airspace = std::make_unique<airspace::Airspace>(
        storage, document->analyzer(), document->model(), ground,
        options.autosaveDirectory.isEmpty() ? QString() : options.autosaveDirectory + QStringLiteral("/drawn-zones.geojson"));

    if (options.vehicles) {
        m_fleet = std::make_unique<VehicleFleet>(m_hciClient.get(), ground);
        m_fleet->setFenceBuilder(airspace::vciFenceFor); // a VCI vehicle's fence is made where the zones are
        m_fleet->setCertificateStore(&m_connection->certificates()); // vci+tls:// certificates beside the server's
        m_missions->preparation()->setFleet(m_fleet.get()); // Process and Upload choose from every vehicle of the fleet
        // Every route given to a vehicle (the open one chosen for it, uploads, flights), for the map and the list.
        m_fleetRoutes = std::make_unique<FleetRoutes>(m_fleet.get(), document, m_missions->preparation());
        // The open route against every route another vehicle holds or flies: a rule on its analyzer.
        m_deconfliction = std::make_unique<deconfliction::RouteDeconfliction>(m_fleetRoutes.get(), m_missions->preparation(),
                                                                              document->analyzer());
    }

    // Manned traffic: the receiver's feed (the option, else the setting) and the server's list.
    m_traffic = std::make_unique<traffic::Traffic>(storage, m_hciClient.get(), options.sbsAddress);
    m_offlineMaps = std::make_unique<maptiles::OfflineMaps>(storage);
    // Each vehicle's video: a receiver per vehicle a view shows (GStreamer started with the first).
    // Its recordings beside the flight logs, in their folder's video/.
    if (m_fleet)
        m_video = std::make_unique<video::VehicleVideo>(
            storage, options.flightLogDirectory.isEmpty() ? QString() : options.flightLogDirectory + QStringLiteral("/video"));
    // The pre-flight checklists: the gate on the fleet's Arm, take-off and Auto, over the vehicles,
    // their routes and the open route's check.
    if (m_fleet)
        m_preflight = std::make_unique<preflight::PreflightChecklists>(m_fleet.get(), m_fleetRoutes.get(), document,
                                                                       m_missions->preparation(), options.checklistDirectory);
    // The gamepads' buttons, for the command bar (through the checklist and the confirmation).
    if (m_fleet)
        m_gamepads = std::make_unique<gamepad::GamepadCommands>(storage);
    // Closest-approach alerts: into the fleet's command log, which the flight recorder follows.
    if (m_fleet)
        m_proximity = std::make_unique<deconfliction::ProximityMonitor>(m_fleet.get(), m_traffic->picture());
    // Zone alerts beside them, in the same banner and log: the zones the operator sees and, per
    // vehicle, the route fence that went up with its mission.
    MissionUploader *uploader = m_missions->preparation()->uploader();
    if (m_fleet) {
        m_zoneAlerts = std::make_unique<airspace::ZoneAlertMonitor>(m_fleet.get(), ground);
        m_uploadedFenceAlerts = std::make_unique<airspace::UploadedFenceAlerts>(uploader, m_zoneAlerts.get());
    }
    // One airspace for the check, the alerts and the fence: what the operator sees is what a
    // vehicle is warned of and carries.
    m_airspaceToVehicles = std::make_unique<airspace::AirspaceToVehicles>(m_airspace.get(), uploader, m_zoneAlerts.get());
    // The server's zones where the maps look (aerodromes and custom ones), into the same store.
    m_serverZones = std::make_unique<airspace::ServerZones>(m_hciClient.get());
    QObject::connect(m_airspace.get(), &airspace::Airspace::areaChanged, m_serverZones.get(),
                     [this] { m_serverZones->setViewBox(m_airspace->area()); });
    QObject::connect(m_serverZones.get(), &airspace::ServerZones::zonesChanged, m_airspace.get(),
                     [this] { m_airspace->setServerZones(m_serverZones->zones()); });
    m_zoneSharing = std::make_unique<airspace::ZoneSharing>(m_airspace.get(), m_serverZones.get());
    // Published zone files fetched from a URL: their copies kept for flying offline, read as zone files.
    m_zoneFeed = std::make_unique<airspace::ZoneFeed>(options.zoneFeedDirectory);
    QObject::connect(m_zoneFeed.get(), &airspace::ZoneFeed::fetched, m_airspace.get(), &airspace::Airspace::loadFeedCopy);

    if (!options.autosaveDirectory.isEmpty()) {
        // Recovery looks first, so the autosave of this run takes a slot of its own.
        m_recovery = std::make_unique<AutosaveRecovery>(document, options.autosaveDirectory);
        m_autosave = std::make_unique<RouteAutosave>(document, options.autosaveDirectory);
        QObject::connect(m_connection.get(), &ConnectionController::ready, m_autosave.get(),
                         [this] { m_autosave->setServer(m_connection->server(), m_connection->user()); });
        // A server route's autosaved edits are restored only when signed in where they belong.
        QObject::connect(m_connection.get(), &ConnectionController::stateChanged, m_recovery.get(), [this] {
            const bool ready = m_connection->isReady();
            m_recovery->setSession(ready ? m_connection->server() : QString(), ready ? m_connection->user() : QString());
        });
    }

    // Every session is recorded without the operator asking: a log per run in the folder given.
    const QString logPath = options.flightLogDirectory.isEmpty()
        ? QString() : flightlog::FlightRecorder::sessionPath(options.flightLogDirectory);
    m_recorder = std::make_unique<flightlog::FlightRecorder>(flightlog::FlightRecorder::Options{logPath, {}, kRecorderFlushMs});
    // The operator's size cap and folder limit, applied before the recorder starts.
    m_recordingSettings = std::make_unique<flightlog::RecordingSettings>(storage, m_recorder.get());
    if (!logPath.isEmpty() && !m_recorder->start(&m_recorderError)) // flying goes on without a log
        qCWarning(lcClientGraph).noquote() << "flight recorder:" << m_recorderError;
    if (m_fleet)
        m_fleetRecording = std::make_unique<flightlog::FleetRecording>(m_fleet.get(), m_recorder.get(), m_session.get());

    m_replay = std::make_unique<flightlog::ReplayController>();
    m_comparison = std::make_unique<flightlog::ComparisonController>(m_replay.get());
    m_serverHistory = std::make_unique<flightlog::ServerHistoryRequest>(m_hciClient.get(), m_replay.get());
    m_serverHistory->setFleet(m_fleet.get());
    m_photos = std::make_unique<coverage::PhotoSurvey>(m_replay.get());
    m_photos->setRouteOpener([document = m_missions->document()](mission::Route route, const QString &text) { document->open(std::move(route), text); });
    // A mission stopped half-way: the rest opened in the editor, chosen for its vehicle, so every rule
    // checks it and it goes up through the same gate.
    if (m_fleet) {
        m_resume = std::make_unique<resume::MissionResume>(m_fleet.get(), m_fleetRoutes.get());
        m_resume->setRouteOpener([document = m_missions->document(), preparation = m_missions->preparation()](
                                     mission::Route route, const QString &text, const QString &vehicleId) {
            document->open(std::move(route), text);
            preparation->setVehicleId(vehicleId);
        });
    }

    qCInfo(lcClientGraph).noquote() << "wired:" << wiring().join(QStringLiteral("; "));
}

// Torn down in the reverse order of the wiring: users before what they use.
ClientGraph::~ClientGraph()
{
    m_airspaceToVehicles.reset();
    m_uploadedFenceAlerts.reset();
    m_resume.reset();
    m_photos.reset();
    m_serverHistory.reset();
    m_comparison.reset();
    m_replay.reset();
    m_fleetRecording.reset();
    m_recordingSettings.reset();
    m_recorder.reset();
    m_autosave.reset();
    m_recovery.reset();
    m_zoneAlerts.reset();
    m_proximity.reset();
    m_deconfliction.reset();
    m_offlineMaps.reset();
    m_video.reset();
    m_gamepads.reset();
    m_preflight.reset();
    m_traffic.reset();
    m_zoneFeed.reset();
    m_zoneSharing.reset();
    m_serverZones.reset();
    m_fleetRoutes.reset();
    m_fleet.reset();
    m_airspace.reset();
    m_endurance.reset();
    m_missions.reset();
    m_elevation.reset();
    m_connection.reset();
    m_hciClient.reset();
    m_session.reset();
}

terrain::ElevationService *ClientGraph::elevation()
{
    return m_elevation->service();
}

void ClientGraph::useDem(const QString &path)
{
    m_elevation->configure(path, m_storage->value(QStringLiteral("terrain/sourceOrder")).toStringList());
}

terrain::ElevationService *ClientGraph::elevationForQml() const
{
    return m_elevation->service();
}

// i18n: not text below (the wiring is a diagnostic for the log and the tests, not for the operator)
QStringList ClientGraph::wiring() const
{
    RouteDocument *document = m_missions->document();
    const terrain::ElevationService *ground = m_elevation->service();
    const auto &rules = document->analyzer()->rules();
    const bool terrainRule = std::any_of(rules.begin(), rules.end(), [&](const auto &r) { return r == m_elevation->rule(); });
    const bool enduranceRule = std::any_of(rules.begin(), rules.end(), [&](const auto &r) { return r == m_endurance->rule(); });
    QStringList lines;
    lines << QStringLiteral("terrain sources: %1").arg(ground->sourceNames().join(QStringLiteral(", ")))
          << QStringLiteral("route validation: %1").arg(yesNo(terrainRule, "with the terrain rule", "without terrain"))
          << QStringLiteral("endurance: %1").arg(yesNo(enduranceRule, "the route's estimate and rule", "none"))
          << QStringLiteral("airspace: %1").arg(yesNo(std::any_of(rules.begin(), rules.end(), [&](const auto &r) { return r == m_airspace->rule(); }),
                                                      "the zones' rule on the route", "none"))
          << QStringLiteral("height conversions: %1").arg(yesNo(document->editor()->hasGroundLookup(), "through the ground", "none"))
          << QStringLiteral("vehicles: %1").arg(!m_fleet ? QStringLiteral("none")
                                                : m_fleet->elevation() == ground ? QStringLiteral("fleet planning over the ground")
                                                                                 : QStringLiteral("fleet without ground"))
          << QStringLiteral("upload chooser: %1").arg(yesNo(m_fleet && m_missions->preparation()->fleet() == m_fleet.get(), "the fleet", "none"))
          << QStringLiteral("traffic: the server's ADS-B list; receiver %1").arg(m_traffic->receiverAddress().isEmpty() ? QStringLiteral("off") : m_traffic->receiverAddress())
          << QStringLiteral("fleet routes: %1").arg(yesNo(m_fleetRoutes != nullptr, "the open route's vehicle and every upload", "none"))
          << QStringLiteral("route deconfliction: %1").arg(yesNo(m_deconfliction && std::any_of(rules.begin(), rules.end(), [&](const auto &r) { return r == m_deconfliction->rule(); }), "against the fleet's routes", "none"))
          << QStringLiteral("video: %1").arg(yesNo(m_video != nullptr, "a receiver per vehicle shown, its URL or video_stream_uri", "none"))
          << QStringLiteral("preflight: %1").arg(yesNo(m_preflight && m_fleet->commands()->gate() == m_preflight.get(), "a checklist per vehicle type, the gate on arm, take-off and auto", "none"))
          << QStringLiteral("gamepads: %1").arg(yesNo(m_gamepads != nullptr, "buttons to the command bar, SDL started when the operator enables them", "none"))
          << QStringLiteral("proximity alerts: %1").arg(yesNo(m_proximity != nullptr, "the fleet and the traffic", "none"))
          << QStringLiteral("zone alerts: %1").arg(yesNo(m_zoneAlerts != nullptr, "the fleet against the airspace", "none"))
          << QStringLiteral("uploaded fences: %1").arg(yesNo(m_uploadedFenceAlerts && m_uploadedFenceAlerts->isFollowing(), "each vehicle's own zone alerts", "none"))
          << QStringLiteral("upload fence: %1").arg(yesNo(m_airspaceToVehicles->isFollowing(), "the airspace beyond the route's own fence", "none"))
          << QStringLiteral("zone feeds: %1").arg(yesNo(!m_zoneFeed->folder().isEmpty(), "kept for flying offline, read into the airspace", "nowhere to keep them"))
          << QStringLiteral("autosave: %1").arg(yesNo(m_autosave && m_autosave->isActive(), "on", "off"))
          << QStringLiteral("recovery: %1").arg(yesNo(m_recovery != nullptr, "on", "off"))
          << QStringLiteral("flight recorder: %1").arg(yesNo(m_recorder->isRecording(), "recording", "off"))
          << QStringLiteral("fleet recording: %1").arg(yesNo(m_fleetRecording != nullptr, "on", "off"))
          << QStringLiteral("server history: %1").arg(yesNo(m_fleet && m_serverHistory->fleet() == m_fleet.get(), "from the fleet", "no fleet"))
          << QStringLiteral("photos: %1").arg(yesNo(m_photos != nullptr, "the replayed log's, placed and their coverage judged; the gaps re-flown in the mission editor", "none"))
          << QStringLiteral("resume: %1").arg(yesNo(m_resume != nullptr, "a mission stopped half-way finished from its last photo or waypoint, in the mission editor", "none"));
    return lines;
}

} // namespace sortie::client
