#include "SortieUi.h"

#include "Airspace.h"
#include "AppSettings.h"
#include "AutosaveRecovery.h"
#include "ClientGraph.h"
#include "ComparisonController.h"
#include "ConnectionController.h"
#include "ElevationService.h"
#include "FleetRoutes.h"
#include "MissionController.h"
#include "OfflineMaps.h"
#include "ProximityMonitor.h"
#include "ZoneAlertMonitor.h"
#include "RecordingSettings.h"
#include "ReplayController.h"
#include "RouteDeconfliction.h"
#include "RouteEndurance.h"
#include "ServerHistoryRequest.h"
#include "Traffic.h"
#include "Translations.h"
#include "ZoneSharing.h"
#include "VehicleFleet.h"

#include <QQmlEngine>

namespace sortie::ui {

void addImportPaths(QQmlEngine &engine)
{
    engine.addImportPath(QStringLiteral("qrc:/qt/qml"));
}

QVariantMap mainWindowProperties(client::ClientGraph &graph, AppSettings &settings, Translations &translations)
{
    return {{QStringLiteral("appSettings"), QVariant::fromValue(&settings)},
            {QStringLiteral("translations"), QVariant::fromValue(&translations)},
            {QStringLiteral("connection"), QVariant::fromValue<QObject *>(&graph.connection())},
            {QStringLiteral("missions"), QVariant::fromValue<QObject *>(&graph.missions())},
            {QStringLiteral("fleet"), QVariant::fromValue<QObject *>(graph.fleet())},
            {QStringLiteral("elevation"), QVariant::fromValue<QObject *>(graph.elevation())},
            {QStringLiteral("replay"), QVariant::fromValue<QObject *>(&graph.replay())},
            {QStringLiteral("comparison"), QVariant::fromValue<QObject *>(&graph.comparison())},
            {QStringLiteral("serverHistory"), QVariant::fromValue<QObject *>(&graph.serverHistory())},
            {QStringLiteral("recordingSettings"), QVariant::fromValue<QObject *>(&graph.recordingSettings())},
            {QStringLiteral("recovery"), QVariant::fromValue<QObject *>(graph.recovery())},
            {QStringLiteral("endurance"), QVariant::fromValue<QObject *>(&graph.endurance())},
            {QStringLiteral("traffic"), QVariant::fromValue<QObject *>(&graph.traffic())},
            {QStringLiteral("offlineMaps"), QVariant::fromValue<QObject *>(&graph.offlineMaps())},
            {QStringLiteral("fleetRoutes"), QVariant::fromValue<QObject *>(graph.fleetRoutes())},
            {QStringLiteral("proximity"), QVariant::fromValue<QObject *>(graph.proximity())},
            {QStringLiteral("zoneAlerts"), QVariant::fromValue<QObject *>(graph.zoneAlerts())},
            {QStringLiteral("deconfliction"), QVariant::fromValue<QObject *>(graph.deconfliction())},
            {QStringLiteral("airspace"), QVariant::fromValue<QObject *>(&graph.airspace())},
            {QStringLiteral("zoneSharing"), QVariant::fromValue<QObject *>(&graph.zoneSharing())}};
}

} // namespace sortie::ui
