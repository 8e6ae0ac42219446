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
    // The client's services, built and wired by core's ClientGraph and handed over once (ui::MainWindow).
    // Each page takes what it uses from it; `graph.recovery` is null in a program or fixture that
    // keeps no autosave folder, the fleet's alerts are null in one without vehicles.
    required property ClientGraph graph
    // The colours, spacing and type sizes (ui/theme): made by ui::MainWindow, following the setting.
    required property Theme theme
    property string connectionState: graph.connection.state
    property string connectionStateText: graph.connection.stateText  // the state in the operator's words
    property string connectionDetail: graph.connection.statusDetail

    property alias currentPage: tabs.currentIndex
    property alias loginPage: loginPage
    property alias missionPage: missionPage
    property alias telemetryPage: telemetryPage
    property alias helpOverlay: help
    property alias restoreDialog: restoreDialog
    readonly property bool dark: theme.darkGround
    readonly property MapView activeMap: tabs.currentIndex === 2 ? telemetryPage.map : missionPage.map

    width: 1280
    height: 800
    minimumWidth: 800
    minimumHeight: 500
    title: qsTr("Sortie")

    // The controls' palette is the theme's (every page and dialog inherits it).
    palette.window: theme.window
    palette.windowText: theme.windowText
    palette.base: theme.base
    palette.alternateBase: theme.alternateBase
    palette.text: theme.text
    palette.button: theme.button
    palette.buttonText: theme.buttonText
    palette.brightText: theme.windowText
    palette.highlight: theme.highlight
    palette.highlightedText: theme.highlightedText
    palette.placeholderText: theme.placeholderText
    palette.toolTipBase: theme.toolTipBase
    palette.toolTipText: theme.toolTipText
    palette.link: theme.link
    palette.light: theme.light
    palette.midlight: theme.midlight
    palette.mid: theme.mid
    palette.dark: theme.dark
    palette.shadow: theme.shadow

    function showPage(index) { tabs.currentIndex = index }
    function toggleHelp() { help.opened ? help.close() : help.open() }
    function openMapSource() { mapSourceDialog.open() }
    function focusMap() { window.activeMap.forceActiveFocus() }
    function saveRoute() { showPage(1); graph.missions.save() }
    function undo() { if (missionPage.zoneEditing) graph.airspace.editor.undo(); else graph.missions.document.undo() }
    function redo() { if (missionPage.zoneEditing) graph.airspace.editor.redo(); else graph.missions.document.redo() }
    function deleteSelection() { if (currentPage === 1) graph.missions.document.editor.removeRows(graph.missions.document.selectedRows) }
    function processRoute() { graph.missions.preparation.process() }
    function toggleFullScreen() { window.visibility = window.visibility === Window.FullScreen ? Window.Windowed : Window.FullScreen }

    Connections {
        target: window.graph.connection
        function onReady() { tabs.currentIndex = 1 }
    }
    // A resumed mission opens in the mission editor: the operator goes there to check and upload it.
    Connections {
        target: window.graph.resume
        function onOpened() { tabs.currentIndex = 1 }
    }

    DisplayUnits {
        id: units
        systemName: window.appSettings.units
        language: window.translations.active   // numbers in the language's format
    }

    GlanceStatus {
        id: glance
        connection: window.graph.connection
        fleet: window.graph.fleet
        chosen: telemetryPage.current
    }

    header: ToolBar {
        RowLayout {
            anchors.fill: parent
            spacing: 0
            RowLayout {
                Layout.fillWidth: true
                TabBar {
                    id: tabs
                    objectName: "pageTabs"
                    // As wide as its three tabs' words, whatever room the glance leaves.
                    Layout.preferredWidth: loginTab.implicitWidth + missionTab.implicitWidth + telemetryTab.implicitWidth + 2 * spacing
                    Layout.minimumWidth: Layout.preferredWidth
                    TabButton { id: loginTab; text: qsTr("Login"); objectName: "loginTab"; width: implicitWidth }
                    TabButton { id: missionTab; text: qsTr("Mission"); objectName: "missionTab"; width: implicitWidth }
                    TabButton { id: telemetryTab; text: qsTr("Live telemetry"); objectName: "telemetryTab"; width: implicitWidth }
                }
                // The connection, the vehicle, its GPS, battery and link at a glance, in the room
                // the tabs and the buttons leave (words elide first).
                GlanceBar {
                    objectName: "glanceBar"
                    Layout.fillWidth: true
                    Layout.minimumWidth: 0
                    Layout.leftMargin: window.theme.spacing
                    status: glance
                    theme: window.theme
                }
                Item { Layout.fillWidth: true } // the buttons keep to the right
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
                            theme: window.theme
                            offlineMaps: window.graph.offlineMaps
                            routeModel: window.graph.missions.document.model
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
                        sourceComponent: FlightLogSettingsDialog { settings: window.graph.recordingSettings; theme: window.theme }
                    }
                }
                ToolButton {
                    // How Sortie shows things: units, language and colours, each applied at once.
                    id: displayButton
                    objectName: "displayButton"
                    text: qsTr("Display…")
                    onClicked: displaySettings.opened ? displaySettings.close() : displaySettings.open()
                    ToolTip.visible: hovered && !displaySettings.opened
                    ToolTip.text: qsTr("Units, language and colours")
                    Popup {
                        id: displaySettings
                        objectName: "displaySettings"
                        y: displayButton.height
                        x: displayButton.width - width
                        padding: window.theme.spacing
                        GridLayout {
                            columns: 2
                            columnSpacing: window.theme.spacing
                            rowSpacing: window.theme.smallSpacing
                            Label { textFormat: Text.PlainText; text: qsTr("Units") }
                            Button {
                                objectName: "unitsButton"
                                Layout.fillWidth: true
                                Layout.preferredHeight: window.theme.controlHeight
                                text: units.imperial ? qsTr("ft, mph") : qsTr("m, m/s")
                                onClicked: window.appSettings.units = units.imperial ? "metric" : "imperial"
                                ToolTip.visible: hovered
                                ToolTip.text: qsTr("Switch between metric and imperial units")
                            }
                            Label { textFormat: Text.PlainText; text: qsTr("Language") }
                            ComboBox {
                                id: languageBox
                                objectName: "languageBox"
                                Layout.fillWidth: true
                                Layout.preferredHeight: window.theme.controlHeight
                                model: window.translations.languageNames
                                // The list is made anew in each language, and a choice made sets the index
                                // itself: each time the box goes back to showing the settings' language.
                                onModelChanged: currentIndex = Qt.binding(() => window.translations.chosenLanguage)
                                // Wide enough for the longest name in the list, not more.
                                implicitContentWidthPolicy: ComboBox.WidestText
                                onActivated: index => {
                                    window.translations.chooseLanguage(index)
                                    currentIndex = Qt.binding(() => window.translations.chosenLanguage)
                                }
                                ToolTip.visible: hovered
                                ToolTip.text: qsTr("The language of Sortie, applied at once")
                            }
                            Label { textFormat: Text.PlainText; text: qsTr("Colours") }
                            ComboBox {
                                id: schemeBox
                                objectName: "colourSchemeBox"
                                Layout.fillWidth: true
                                Layout.preferredHeight: window.theme.controlHeight
                                model: window.theme.schemeNames
                                // As the language box: the theme's scheme (it follows the setting) is shown.
                                onModelChanged: currentIndex = Qt.binding(() => window.theme.schemeIndex)
                                implicitContentWidthPolicy: ComboBox.WidestText
                                onActivated: index => {
                                    window.appSettings.colourScheme = window.theme.schemeCodes[index]
                                    currentIndex = Qt.binding(() => window.theme.schemeIndex)
                                }
                                ToolTip.visible: hovered
                                ToolTip.text: qsTr("The system's colours, light, dark, or high contrast for sunlight")
                            }
                        }
                    }
                }
                ToolButton {
                    text: "?"
                    onClicked: window.toggleHelp()
                    ToolTip.visible: hovered
                    ToolTip.text: qsTr("Keyboard shortcuts (F1)")
                }
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
            graph: window.graph
            theme: window.theme
        }
        MissionPage {
            id: missionPage
            objectName: "missionPage"
            graph: window.graph
            units: units
            theme: window.theme
            mapSource: window.appSettings.mapSource
            tileUrlTemplate: window.appSettings.tileUrlTemplate
            mbtilesFile: window.appSettings.mbtilesFile
            orthophotoFile: window.appSettings.orthophotoFile
            orthophotoOpacity: window.appSettings.orthophotoOpacity
            tilePackFile: window.graph.offlineMaps.packFile
            tilesCacheOnly: window.graph.offlineMaps.cacheOnly
            offlineArea: offlineMapsDialog.item && offlineMapsDialog.item.visible ? window.graph.offlineMaps.areaCorners : []
            onAreaDrawn: corners => { window.graph.offlineMaps.usePolygonArea(corners); offlineMapsDialog.item.open() }
            onAreaRectangleDrawn: (corner, opposite) => { window.graph.offlineMaps.useRectangleArea(corner, opposite); offlineMapsDialog.item.open() }
            onAreaDrawingCancelled: offlineMapsDialog.item.open()
        }
        TelemetryPage {
            id: telemetryPage
            objectName: "telemetryPage"
            graph: window.graph
            units: units
            theme: window.theme
            mapSource: window.appSettings.mapSource
            tileUrlTemplate: window.appSettings.tileUrlTemplate
            mbtilesFile: window.appSettings.mbtilesFile
            orthophotoFile: window.appSettings.orthophotoFile
            orthophotoOpacity: window.appSettings.orthophotoOpacity
            tilePackFile: window.graph.offlineMaps.packFile
            tilesCacheOnly: window.graph.offlineMaps.cacheOnly
        }
    }

    footer: StatusBar {
        objectName: "statusBar"
        connectionState: window.connectionState
        connectionStateText: window.connectionStateText
        connectionDetail: window.connectionDetail
        map: window.activeMap
        units: units
        theme: window.theme
    }

    // Every attached tool tip (`ToolTip.text: …`) is one ToolTip the engine shares: its text is plain,
    // so a name from outside in a tool tip (a route's, a vehicle's, a server's message) is shown as it
    // is, never as HTML (issue 36). Attached to an Item: the window itself is none.
    Item {
        Component.onCompleted: ToolTip.toolTip.contentItem.textFormat = Text.PlainText
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
        recovery: window.graph.recovery
        theme: window.theme
        // Also alone, to say what went wrong with an autosave (a file kept aside) until read.
        visible: window.graph.recovery !== null && (window.graph.recovery.available || window.graph.recovery.message.length > 0)
        onRestored: {
            window.showPage(1)
            Qt.callLater(() => missionPage.routeLayer.fitToMap(60))
        }
    }
    Binding { // the pack and the download follow the web source chosen in Map source
        target: window.graph.offlineMaps
        property: "urlTemplate"
        value: window.appSettings.tileUrlTemplate
    }
    MapSourceDialog {
        id: mapSourceDialog
        objectName: "mapSourceDialog"
        appSettings: window.appSettings
        theme: window.theme
    }
}
