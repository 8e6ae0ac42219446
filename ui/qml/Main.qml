import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The main window: Login, Mission and Live telemetry pages, a status bar that always shows
// the connection state, keyboard shortcuts with a help overlay (F1).
ApplicationWindow {
    id: window
    required property AppSettings appSettings
    // The client's controllers, made in C++ (app/sortie). Each may still be missing here (a test
    // of the shell alone, fixtures that make only some of them); the views then show what they can
    // without it. They become `required` once every program and fixture builds the whole graph
    // (core/client's ClientGraph); the pages below already require each one explicitly.
    property ConnectionController connection: null
    property MissionController missions: null
    property VehicleFleet fleet: null
    property ElevationService elevation: null   // the terrain service (core/terrain), when there is one
    // Flight-log replay (the timeline on the telemetry page); null when the program has none.
    property ReplayController replay: null
    property ComparisonController comparison: null
    property ServerHistoryRequest serverHistory: null   // the server's history into the replay
    property RecordingSettings recordingSettings: null  // the flight logs' folder and limits (Logs…)
    // Edits a previous run left unsaved, offered at start.
    property AutosaveRecovery recovery: null
    property QtObject endurance: null   // the open route's endurance (RouteEndurance; its views are to come)
    property string connectionState: connection ? connection.state : "Disconnected"
    property string connectionDetail: connection ? connection.statusDetail : ""

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
    function saveRoute() { if (missions) { showPage(1); missions.save() } }
    function undo() { if (missions) missions.document.undo() }
    function redo() { if (missions) missions.document.redo() }
    function deleteSelection() { if (missions && currentPage === 1) missions.document.editor.removeRows(missions.document.selectedRows) }
    function processRoute() { if (missions) missions.process() }
    function toggleFullScreen() { window.visibility = window.visibility === Window.FullScreen ? Window.Windowed : Window.FullScreen }

    Connections {
        target: window.connection
        function onReady() { tabs.currentIndex = 1 }
    }

    DisplayUnits {
        id: units
        systemName: window.appSettings.units
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
                objectName: "logSettingsButton"
                visible: window.recordingSettings !== null
                text: qsTr("Logs…")
                onClicked: logSettingsDialog.item.open()
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Where flight logs are recorded, and how much they may take")
                Loader {
                    id: logSettingsDialog
                    active: window.recordingSettings !== null
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
            units: units
            dark: window.dark
            mapSource: window.appSettings.mapSource
            tileUrlTemplate: window.appSettings.tileUrlTemplate
            mbtilesFile: window.appSettings.mbtilesFile
        }
        TelemetryPage {
            id: telemetryPage
            objectName: "telemetryPage"
            fleet: window.fleet
            replay: window.replay
            serverHistory: window.serverHistory
            comparison: window.comparison
            units: units
            dark: window.dark
            mapSource: window.appSettings.mapSource
            tileUrlTemplate: window.appSettings.tileUrlTemplate
            mbtilesFile: window.appSettings.mbtilesFile
        }
    }

    footer: StatusBar {
        objectName: "statusBar"
        connectionState: window.connectionState
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
    MapSourceDialog {
        id: mapSourceDialog
        objectName: "mapSourceDialog"
        appSettings: window.appSettings
    }
}
