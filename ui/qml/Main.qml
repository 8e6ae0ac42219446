import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The main window: Login, Mission and Live telemetry pages, a status bar that always shows
// the connection state, keyboard shortcuts with a help overlay (F1).
ApplicationWindow {
    id: window
    required property AppSettings appSettings
    required property Translations translations     // the UI's language: the selector's list, the one in use
    // The client's controllers: the one client graph (core/client's ClientGraph), handed over by
    // ui::mainWindowProperties. Every one is there; only `recovery` is null, in a program or fixture
    // that keeps no autosave folder.
    required property ConnectionController connection
    required property MissionController missions
    required property VehicleFleet fleet
    required property ElevationService elevation   // the terrain service (core/terrain; "none" at least)
    required property ReplayController replay       // flight-log replay: the telemetry page's timeline
    required property ComparisonController comparison
    required property ServerHistoryRequest serverHistory   // the server's history into the replay
    required property RecordingSettings recordingSettings  // the flight logs' folder and limits (Logs…)
    required property AutosaveRecovery recovery     // edits a previous run left unsaved; may be null
    required property RouteEndurance endurance      // will the battery last: the open route's endurance
    required property Traffic traffic               // manned traffic: ADS-B from a receiver and the server
    required property OfflineMaps offlineMaps       // maps taken offline: the download and the cache-only setting
    required property FleetRoutes fleetRoutes       // every route given to a vehicle: drawn on both maps, listed beside them
    required property ProximityMonitor proximity    // closest-approach alerts in flight; null without vehicles
    required property ZoneAlertMonitor zoneAlerts   // zone alerts in flight; null without vehicles
    required property RouteDeconfliction deconfliction  // the open route's 4D conflicts; null without vehicles
    required property Airspace airspace             // the zones: both maps, the zone panel, the route's airspace check
    required property ZoneSharing zoneSharing       // drawn zones to the server; the server's custom zones edited, deleted
    property string connectionState: connection.state
    property string connectionStateText: connection.stateText  // the state in the operator's words
    property string connectionDetail: connection.statusDetail

    property alias currentPage: tabs.currentIndex
    property alias loginPage: loginPage
    property alias missionPage: missionPage
    property alias telemetryPage: telemetryPage
    property alias helpOverlay: help
    property alias restoreDialog: restoreDialog
    readonly property bool dark: palette.window.hslLightness < 0.5
    readonly property MapView activeMap: tabs.currentIndex === 2 ? telemetryPage.map : missionPage.map

    width: 1280
    height: 800
    minimumWidth: 800
    minimumHeight: 500
    title: qsTr("Sortie")

    function showPage(index) { tabs.currentIndex = index }
    function toggleHelp() { help.opened ? help.close() : help.open() }
    function openMapSource() { mapSourceDialog.open() }
    function focusMap() { window.activeMap.forceActiveFocus() }
    function saveRoute() { showPage(1); missions.save() }
    function undo() { if (missionPage.zoneEditing) airspace.editor.undo(); else missions.document.undo() }
    function redo() { if (missionPage.zoneEditing) airspace.editor.redo(); else missions.document.redo() }
    function deleteSelection() { if (currentPage === 1) missions.document.editor.removeRows(missions.document.selectedRows) }
    function processRoute() { missions.preparation.process() }
    function toggleFullScreen() { window.visibility = window.visibility === Window.FullScreen ? Window.Windowed : Window.FullScreen }

    Connections {
        target: window.connection
        function onReady() { tabs.currentIndex = 1 }
    }

    DisplayUnits {
        id: units
        systemName: window.appSettings.units
        language: window.translations.active   // numbers in the language's format
    }

    header: ToolBar {
        RowLayout {
            anchors.fill: parent
            TabBar {
                id: tabs
                objectName: "pageTabs"
                Layout.fillWidth: true
                TabButton { text: qsTr("Login"); objectName: "loginTab" }
                TabButton { text: qsTr("Mission"); objectName: "missionTab" }
                TabButton { text: qsTr("Live telemetry"); objectName: "telemetryTab" }
            }
            ToolButton {
                text: qsTr("Map…")
                onClicked: window.openMapSource()
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Choose the map source (Ctrl+M)")
            }
            ToolButton {
                objectName: "offlineMapsButton"
                text: qsTr("Offline…")
                onClicked: { offlineMapsDialog.active = true; offlineMapsDialog.item.open() }
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Download the web map of an area for work without a network")
                Loader { // made when first opened
                    id: offlineMapsDialog
                    active: false
                    sourceComponent: OfflineMapsDialog {
                        offlineMaps: window.offlineMaps
                        routeModel: window.missions.document.model
                        map: window.activeMap
                        // Drawn on the mission map (its zones' polygon tool); the dialog comes back after.
                        onDrawRequested: { window.showPage(1); missionPage.drawArea() }
                    }
                }
            }
            ToolButton {
                objectName: "logSettingsButton"
                text: qsTr("Logs…")
                onClicked: { logSettingsDialog.active = true; logSettingsDialog.item.open() }
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Where flight logs are recorded, and how much they may take")
                Loader { // made when first opened: the start-up does not pay for it
                    id: logSettingsDialog
                    active: false
                    sourceComponent: FlightLogSettingsDialog { settings: window.recordingSettings }
                }
            }
            ToolButton {
                objectName: "unitsButton"
                text: units.imperial ? qsTr("ft, mph") : qsTr("m, m/s")
                onClicked: window.appSettings.units = units.imperial ? "metric" : "imperial"
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Switch between metric and imperial units")
            }
            ComboBox {
                id: languageBox
                objectName: "languageBox"
                model: window.translations.languages
                textRole: "name"
                valueRole: "code"
                // The list is made anew in each language: the choice is found again in it.
                onModelChanged: currentIndex = Qt.binding(() => Math.max(0, indexOfValue(window.appSettings.language)))
                // Wide enough for the longest name in the list, not more.
                implicitContentWidthPolicy: ComboBox.WidestText
                onActivated: window.appSettings.language = currentValue
                ToolTip.visible: hovered
                ToolTip.text: qsTr("The language of Sortie, applied at once")
            }
            ToolButton {
                text: "?"
                onClicked: window.toggleHelp()
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Keyboard shortcuts (F1)")
            }
        }
    }

    StackLayout {
        id: pages
        anchors.fill: parent
        currentIndex: tabs.currentIndex
        LoginPage {
            id: loginPage
            objectName: "loginPage"
            appSettings: window.appSettings
            connection: window.connection
        }
        MissionPage {
            id: missionPage
            objectName: "missionPage"
            missions: window.missions
            vehicleModel: window.fleet
            elevation: window.elevation
            endurance: window.endurance
            traffic: window.traffic
            fleetRoutes: window.fleetRoutes
            deconfliction: window.deconfliction
            airspace: window.airspace
            zoneSharing: window.zoneSharing
            units: units
            dark: window.dark
            mapSource: window.appSettings.mapSource
            tileUrlTemplate: window.appSettings.tileUrlTemplate
            mbtilesFile: window.appSettings.mbtilesFile
            orthophotoFile: window.appSettings.orthophotoFile
            orthophotoOpacity: window.appSettings.orthophotoOpacity
            tilePackFile: window.offlineMaps.packFile
            tilesCacheOnly: window.offlineMaps.cacheOnly
            offlineArea: offlineMapsDialog.item && offlineMapsDialog.item.visible ? window.offlineMaps.areaCorners : []
            onAreaDrawn: corners => { window.offlineMaps.usePolygonArea(corners); offlineMapsDialog.item.open() }
            onAreaRectangleDrawn: (corner, opposite) => { window.offlineMaps.useRectangleArea(corner, opposite); offlineMapsDialog.item.open() }
            onAreaDrawingCancelled: offlineMapsDialog.item.open()
        }
        TelemetryPage {
            id: telemetryPage
            objectName: "telemetryPage"
            fleet: window.fleet
            endurance: window.endurance
            traffic: window.traffic
            fleetRoutes: window.fleetRoutes
            proximity: window.proximity
            zoneAlerts: window.zoneAlerts
            airspace: window.airspace
            replay: window.replay
            serverHistory: window.serverHistory
            comparison: window.comparison
            units: units
            dark: window.dark
            mapSource: window.appSettings.mapSource
            tileUrlTemplate: window.appSettings.tileUrlTemplate
            mbtilesFile: window.appSettings.mbtilesFile
            orthophotoFile: window.appSettings.orthophotoFile
            orthophotoOpacity: window.appSettings.orthophotoOpacity
            tilePackFile: window.offlineMaps.packFile
            tilesCacheOnly: window.offlineMaps.cacheOnly
        }
    }

    footer: StatusBar {
        objectName: "statusBar"
        connectionState: window.connectionState
        connectionStateText: window.connectionStateText
        connectionDetail: window.connectionDetail
        map: window.activeMap
        units: units
    }

    Shortcuts {
        id: shortcuts
        onHelpRequested: window.toggleHelp()
        onPageRequested: page => window.showPage(page)
        onSaveRequested: window.saveRoute()
        onUndoRequested: window.undo()
        onRedoRequested: window.redo()
        onDeleteRequested: window.deleteSelection()
        onProcessRequested: window.processRoute()
        onMapSourceRequested: window.openMapSource()
        onMapFocusRequested: window.focusMap()
        onFullScreenRequested: window.toggleFullScreen()
    }
    ShortcutHelp {
        id: help
        objectName: "shortcutHelp"
        shortcuts: shortcuts
    }
    RestoreDialog {
        id: restoreDialog
        objectName: "restoreDialog"
        recovery: window.recovery
        // Also alone, to say what went wrong with an autosave (a file kept aside) until read.
        visible: window.recovery !== null && (window.recovery.available || window.recovery.message.length > 0)
        onRestored: {
            window.showPage(1)
            Qt.callLater(() => missionPage.routeLayer.fitToMap(60))
        }
    }
    Binding { // the pack and the download follow the web source chosen in Map source
        target: window.offlineMaps
        property: "urlTemplate"
        value: window.appSettings.tileUrlTemplate
    }
    MapSourceDialog {
        id: mapSourceDialog
        objectName: "mapSourceDialog"
        appSettings: window.appSettings
    }
}
