#pragma once

// The core types QML views hold, registered for Sortie.Ui as uncreatable types so that views
// declare typed properties (`required property Vehicle vehicle`) instead of `var`. The objects
// themselves are made and wired in C++ (app/sortie, tests) and handed to the window.
#include "Airspace.h"
#include "AutosaveRecovery.h"
#include "ClientGraph.h"
#include "CommandLog.h"
#include "CommandPolicy.h"
#include "ElevationService.h"
#include "FlightAlerts.h"
#include "HciTrafficSource.h"
#include "MissionUploader.h"
#include "RoutePreparation.h"
#include "RouteEndurance.h"
#include "EnduranceAdvisory.h"
#include "ConnectionController.h"
#include "MissionController.h"
#include "RouteAnalyzer.h"
#include "RouteConflict.h"
#include "RouteDocument.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "SbsFeed.h"
#include "ServerObjectListModel.h"
#include "ProximityMonitor.h"
#include "ZoneAlertMonitor.h"
#include "RouteDeconfliction.h"
#include "Traffic.h"
#include "OfflineMaps.h"
#include "TrafficPicture.h"
#include "ValidationIssueModel.h"
#include "Vehicle.h"
#include "VehicleFleet.h"
#include "VehicleVideo.h"
#include "PreflightChecklists.h"
#include "MissionResume.h"
#include "GamepadCommands.h"
#include "VehicleChecklist.h"
#include "VideoReceiver.h"
#include "VehicleGroup.h"
#include "FleetRoutes.h"
#include "VehicleLink.h"
#include "ZoneEditor.h"
#include "ZoneFeed.h"
#include "ZoneSharing.h"
#include "ZoneListModel.h"

#include <QAbstractItemModel>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui::qmltypes {

// Any list model, for views that take "a model with these roles" (a page's routeModel, the fly
// view's vehicleModel): Qt 6.4's QtQml.Models knows QAbstractItemModel but gives it no QML name.
struct AbstractItemModelForeign
{
    Q_GADGET
    QML_FOREIGN(QAbstractItemModel)
    QML_NAMED_ELEMENT(AbstractItemModel)
    QML_UNCREATABLE("an abstract class: views are handed a model made in C++ or QML")
};

// The client's services in one object, handed to Main.qml once; a page takes what it uses from it
// (`graph.airspace`), typed by the graph's own properties, so a service needs no name here unless a
// view declares a property of its type.
struct ClientGraphForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::ClientGraph)
    QML_NAMED_ELEMENT(ClientGraph)
    QML_UNCREATABLE("made by the program and handed to the main window")
};

struct ConnectionControllerForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::ConnectionController)
    QML_NAMED_ELEMENT(ConnectionController)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct MissionControllerForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::MissionController)
    QML_NAMED_ELEMENT(MissionController)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct RouteDocumentForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::RouteDocument)
    QML_NAMED_ELEMENT(RouteDocument)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct RouteConflictForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::RouteConflict)
    QML_NAMED_ELEMENT(RouteConflict)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct ServerObjectListModelForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::ServerObjectListModel)
    QML_NAMED_ELEMENT(ServerObjectListModel)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct AutosaveRecoveryForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::AutosaveRecovery)
    QML_NAMED_ELEMENT(AutosaveRecovery)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct VehicleFleetForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::VehicleFleet)
    QML_NAMED_ELEMENT(VehicleFleet)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct FleetRoutesForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::FleetRoutes)
    QML_NAMED_ELEMENT(FleetRoutes)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct VehicleForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::vehicle::Vehicle)
    QML_NAMED_ELEMENT(Vehicle)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct VehicleLinkForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::vehicle::VehicleLink)
    QML_NAMED_ELEMENT(VehicleLink)
    QML_UNCREATABLE("made by the program; here for its State enum")
};
struct RouteModelForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::mission::RouteModel)
    QML_NAMED_ELEMENT(RouteModel)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct RouteEditorForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::mission::RouteEditor)
    QML_NAMED_ELEMENT(RouteEditor)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct RouteAnalyzerForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::mission::RouteAnalyzer)
    QML_NAMED_ELEMENT(RouteAnalyzer)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct ValidationIssueModelForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::mission::ValidationIssueModel)
    QML_NAMED_ELEMENT(ValidationIssueModel)
    QML_UNCREATABLE("made by the program and handed to the views")
};

struct RouteEnduranceForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::endurance::RouteEndurance)
    QML_NAMED_ELEMENT(RouteEndurance)
    QML_UNCREATABLE("made by the program and handed to the views")
};

// Creatable: the fly view makes one for the chosen vehicle (`vehicle`, `endurance`), as it does a
// FlightStatus; the rules are C++ (core/endurance/client), the view only shows them.
struct EnduranceAdvisoryForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::endurance::EnduranceAdvisory)
    QML_NAMED_ELEMENT(EnduranceAdvisory)
};

// Manned traffic (core/traffic): the picture and its two sources, made by the client graph.
struct TrafficForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::traffic::Traffic)
    QML_NAMED_ELEMENT(Traffic)
    QML_UNCREATABLE("made by the program and handed to the views")
};
// Live video (core/video): a vehicle's receiver (its state for the views) and the service that
// makes one per vehicle, both made in C++.
struct VideoReceiverForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::video::VideoReceiver)
    QML_NAMED_ELEMENT(VideoReceiver)
    QML_UNCREATABLE("made by the vehicles' video service")
};
struct VehicleVideoForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::video::VehicleVideo)
    QML_NAMED_ELEMENT(VehicleVideo)
    QML_UNCREATABLE("made by the program and handed to the views")
};
// The pre-flight checklists (core/preflight/client): the fleet's, made by the client graph, and
// one vehicle's list, made by them.
struct PreflightChecklistsForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::preflight::PreflightChecklists)
    QML_NAMED_ELEMENT(PreflightChecklists)
    QML_UNCREATABLE("made by the program and handed to the views")
};
// The offer to finish a mission a vehicle stopped half-way (core/resume/client), made by the client graph.
struct MissionResumeForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::resume::MissionResume)
    QML_NAMED_ELEMENT(MissionResume)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct GamepadCommandsForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::gamepad::GamepadCommands)
    QML_NAMED_ELEMENT(GamepadCommands)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct VehicleChecklistForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::preflight::VehicleChecklist)
    QML_NAMED_ELEMENT(VehicleChecklist)
    QML_UNCREATABLE("made by the pre-flight checklists, one per vehicle")
};
// Maps taken offline (core/maptiles): the Offline maps dialog's controller, made by the client graph.
struct OfflineMapsForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::maptiles::OfflineMaps)
    QML_NAMED_ELEMENT(OfflineMaps)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct AirspaceForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::airspace::Airspace)
    QML_NAMED_ELEMENT(Airspace)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct ZoneListModelForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::airspace::ZoneListModel)
    QML_NAMED_ELEMENT(ZoneListModel)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct ZoneEditorForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::airspace::ZoneEditor)
    QML_NAMED_ELEMENT(ZoneEditor)
    QML_UNCREATABLE("made by the program and handed to the views")
};
// Values the views hold by type (`property drawingTool currentTool`), read by property, never by key.
struct ZoneFieldsForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::airspace::ZoneFields)
    QML_VALUE_TYPE(zoneFields)
};
struct GeoZoneDetailsForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::airspace::GeoZoneDetails)
    QML_VALUE_TYPE(geoZoneDetails)
};
struct DrawingToolForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::mission::DrawingTool)
    QML_VALUE_TYPE(drawingTool)
};
struct ZoneFeedForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::airspace::ZoneFeed)
    QML_NAMED_ELEMENT(ZoneFeed)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct ZoneSharingForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::airspace::ZoneSharing)
    QML_NAMED_ELEMENT(ZoneSharing)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct RouteDeconflictionForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::deconfliction::RouteDeconfliction)
    QML_NAMED_ELEMENT(RouteDeconfliction)
    QML_UNCREATABLE("made by the program and handed to the views")
};
// The in-flight alert contract every monitor keeps: the fly view's AlertBanner takes a list of them.
struct AlertModelForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::vehicle::AlertModel)
    QML_NAMED_ELEMENT(AlertModel)
    QML_UNCREATABLE("each monitor is one; the program makes them")
};
struct ProximityMonitorForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::deconfliction::ProximityMonitor)
    QML_NAMED_ELEMENT(ProximityMonitor)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct ZoneAlertMonitorForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::airspace::ZoneAlertMonitor)
    QML_NAMED_ELEMENT(ZoneAlertMonitor)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct TrafficPictureForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::traffic::TrafficPicture)
    QML_NAMED_ELEMENT(TrafficPicture)
    QML_UNCREATABLE("made by Traffic")
};
struct SbsFeedForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::traffic::SbsFeed)
    QML_NAMED_ELEMENT(SbsFeed)
    QML_UNCREATABLE("made by Traffic")
};
struct HciTrafficSourceForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::traffic::HciTrafficSource)
    QML_NAMED_ELEMENT(HciTrafficSource)
    QML_UNCREATABLE("made by Traffic")
};

struct RoutePreparationForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::RoutePreparation)
    QML_NAMED_ELEMENT(RoutePreparation)
    QML_UNCREATABLE("made by the MissionController")
};

struct MissionUploaderForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::MissionUploader)
    QML_NAMED_ELEMENT(MissionUploader)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct CommandPolicyForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::CommandPolicy)
    QML_NAMED_ELEMENT(CommandPolicy)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct VehicleGroupForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::client::VehicleGroup)
    QML_NAMED_ELEMENT(VehicleGroup)
    QML_UNCREATABLE("made by the VehicleFleet")
};
struct CommandLogForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::vehicle::CommandLog)
    QML_NAMED_ELEMENT(CommandLog)
    QML_UNCREATABLE("made by the program and handed to the views")
};
struct ElevationServiceForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::terrain::ElevationService)
    QML_NAMED_ELEMENT(ElevationService)
    QML_UNCREATABLE("made by the program and handed to the views")
};

} // namespace sortie::ui::qmltypes
