import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Live telemetry: every vehicle (HCI and VCI side by side) on the map, turned to its heading,
// with its trail and home; the chosen one's instruments, plot and command bar.
Page {
    id: page
    required property Theme theme
    property alias map: pane.map
    property alias vehicleLayer: vehicleLayer
    property alias pane: pane
    required property DisplayUnits units
    // The client's services (core's ClientGraph); the page takes what it uses from it.
    required property ClientGraph graph
    readonly property VehicleFleet fleet: graph.fleet   // null in a graph without vehicles
    // A log being replayed takes the place of the live vehicles (the timeline says so).
    readonly property ReplayController replay: graph.replay
    // The server's history for the replay (the timeline's Server history… dialog).
    readonly property ServerHistoryRequest serverHistory: graph.serverHistory
    readonly property ComparisonController comparison: graph.comparison
    // The replayed flight's photos (the timeline's Photos… dialog), drawn where they were taken.
    readonly property PhotoSurvey photos: graph.photos
    // A mission the chosen vehicle stopped half-way, offered to be finished; null without vehicles.
    readonly property MissionResume resume: graph.resume
    // The energy profile and wind the in-flight advice prices with (the mission page chooses them).
    readonly property RouteEndurance endurance: graph.endurance
    readonly property Traffic traffic: graph.traffic   // manned traffic around (ADS-B)
    readonly property VehicleVideo video: graph.video  // each vehicle's live video; null without vehicles
    property alias videoPanel: videoPanel
    // Each vehicle's pre-flight checklist, the gate on Arm and Auto; null without vehicles.
    readonly property PreflightChecklists preflight: graph.preflight
    readonly property GamepadCommands gamepads: graph.gamepads   // buttons as commands; null without vehicles
    // Every route given to a vehicle: drawn under the flight plans, listed under the vehicles.
    readonly property FleetRoutes fleetRoutes: graph.fleetRoutes
    readonly property ProximityMonitor proximity: graph.proximity   // closest-approach alerts (the fleet and the traffic); null without vehicles
    readonly property ZoneAlertMonitor zoneAlerts: graph.zoneAlerts // a vehicle about to enter a zone or leave a fence; null without vehicles
    readonly property Airspace airspace: graph.airspace             // the zones, drawn under everything else
    property alias zoneLayer: zoneLayer
    readonly property bool replaying: replay.active
    property AbstractItemModel vehicleModel: replaying ? replay.fleet : fleet   // any list model with the fleet's role names
    property list<string> plotFields: ["altitudeAgl"]   // what the plot shows, as the operator picked
    readonly property Vehicle current: vehicleLayer.currentIndex < 0 ? null
                                       : replaying ? replay.fleet.vehicleAt(vehicleLayer.currentIndex)
                                       : fleet.vehicleAt(vehicleLayer.currentIndex)
    property string mapSource: "offline"
    property string tileUrlTemplate: ""
    property string mbtilesFile: ""
    property string orthophotoFile: ""
    property real orthophotoOpacity: 0.8
    property string tilePackFile: ""    // the web source's offline pack (OfflineMaps.packFile)
    property bool tilesCacheOnly: false // the web source never uses the network
    readonly property alias advisory: advisory

    // Will the chosen vehicle's battery bring it home? Not for a replayed flight: nothing to send.
    EnduranceAdvisory {
        id: advisory
        objectName: "enduranceAdvisory"
        vehicle: page.replaying ? null : page.current
        endurance: page.endurance
    }

    SplitView {
        anchors.fill: parent
        Pane {
            SplitView.preferredWidth: 250
            SplitView.minimumWidth: 180
            contentWidth: availableWidth
            ColumnLayout {
                anchors.fill: parent
                Label { textFormat: Text.PlainText; text: qsTr("Vehicles"); font.bold: true; font.pixelSize: 16 }
                Label {
                    textFormat: Text.PlainText
                    objectName: "vehicleSummary"
                    visible: vehicleLayer.count === 0
                    text: qsTr("No vehicles. Log in to a server or connect a VCI vehicle.")
                    wrapMode: Text.Wrap
                    Layout.fillWidth: true
                }
                ListView {
                    objectName: "vehicleList"
                    Layout.fillWidth: true
                    Layout.fillHeight: true
                    clip: true
                    model: page.vehicleModel
                    currentIndex: vehicleLayer.currentIndex
                    // A tick puts the vehicle in the group the command bar commands (live fleet only).
                    delegate: RowLayout {
                        id: vehicleRow
                        required property int index
                        required property var model
                        width: ListView.view.width
                        spacing: 0
                        CheckBox {
                            objectName: "vehicleTick"
                            visible: !page.replaying
                            checked: vehicleRow.model.chosen === true
                            onToggled: page.fleet.group.setChosen(vehicleRow.model.vehicleId, checked)
                            ToolTip.visible: hovered
                            ToolTip.text: qsTr("Command together with the other ticked vehicles")
                        }
                        ItemDelegate {
                            Layout.fillWidth: true
                            highlighted: vehicleRow.index === vehicleLayer.currentIndex
                            text: (vehicleRow.model.name !== undefined ? vehicleRow.model.name : qsTr("Vehicle %1").arg(vehicleRow.index + 1))
                                  + (vehicleRow.model.protocol !== undefined ? "  ·  " + vehicleRow.model.protocol + "  ·  " + page.units.formatLinkState(vehicleRow.model.vehicle.linkState) : "")
                            opacity: vehicleRow.model.stale === true ? 0.5 : 1
                            onClicked: { vehicleLayer.currentIndex = vehicleRow.index; vehicleLayer.centerOn(vehicleRow.index) }
                        }
                    }
                }
                RowLayout {
                    Layout.fillWidth: true
                    TextField {
                        id: vciAddress
                        objectName: "vciAddressField"
                        Layout.fillWidth: true
                        placeholderText: "tcp://host:5760"
                        selectByMouse: true
                        ToolTip.visible: hovered
                        ToolTip.text: qsTr("A vehicle reached directly over VCI: tcp://host:port or serial:///dev/ttyX?baud=57600")
                    }
                    Button {
                        objectName: "vciConnectButton"
                        text: qsTr("Add")
                        enabled: vciAddress.text.length > 0
                        onClicked: if (page.fleet.addVciVehicle(vciAddress.text)) vciAddress.text = ""
                    }
                }
                Label {
                    textFormat: Text.PlainText
                    visible: page.fleet.message.length > 0
                    text: page.fleet.message
                    color: page.theme.problemText
                    wrapMode: Text.Wrap
                    Layout.fillWidth: true
                }
                FleetRoutesList {
                    theme: page.theme
                    objectName: "flyFleetRoutes"
                    visible: page.fleetRoutes.count > 0 && !page.replaying
                    Layout.fillWidth: true
                    // Its rows, up to 40 % of the page: the vehicles above keep the rest.
                    Layout.fillHeight: false
                    Layout.preferredHeight: Math.min(implicitHeight, page.height * 0.4)
                    Layout.minimumHeight: Layout.preferredHeight
                    Layout.maximumHeight: Layout.preferredHeight
                    routes: page.fleetRoutes
                    units: page.units
                    currentVehicleRow: vehicleLayer.currentIndex
                }
            }
        }
        ColumnLayout {
            SplitView.fillWidth: true
            spacing: 0
            // The map and the chosen vehicle's video: the video in a corner of the map, or swapped,
            // the video in the map's place and the map in the corner (picture in picture).
            Item {
                id: mapArea
                Layout.fillWidth: true
                Layout.fillHeight: true
            MapPane {
                id: pane
                readonly property bool small: videoPanel.visible && videoPanel.swapped
                x: small ? 8 : 0
                y: small ? mapArea.height - height - 40 : 0  // above the video's URL bar
                width: small ? Math.min(360, mapArea.width / 2) : mapArea.width
                height: small ? Math.min(240, mapArea.height / 2) : mapArea.height
                z: small ? 2 : 0
                units: page.units
                mapSource: page.mapSource
                tileUrlTemplate: page.tileUrlTemplate
                mbtilesFile: page.mbtilesFile
                orthophotoFile: page.orthophotoFile
                orthophotoOpacity: page.orthophotoOpacity
                tilePackFile: page.tilePackFile
                tilesCacheOnly: page.tilesCacheOnly
                theme: page.theme
                ZoneLayer {
                    id: zoneLayer
                    objectName: "flyZoneLayer"
                    anchors.fill: parent
                    map: pane.map
                    airspace: page.airspace
                    PlainToolTip {
                        // Where the mouse is: the zone's name, source and limits.
                        visible: parent.hoverText.length > 0
                        text: parent.hoverText
                        x: parent.hoverPosition.x + 12
                        y: parent.hoverPosition.y + 16
                    }
                }
                FleetRoutesLayer {
                    objectName: "flyFleetRoutesLayer"
                    anchors.fill: parent
                    map: pane.map
                    visible: !page.replaying
                    model: page.fleetRoutes
                    currentVehicleRow: vehicleLayer.currentIndex
                }
                FlightPlanLayer {
                    // Each vehicle's mission under it: flown, ahead, the waypoint it flies to.
                    id: planLayer
                    objectName: "flightPlanLayer"
                    anchors.fill: parent
                    map: pane.map
                    model: page.vehicleModel
                    currentIndex: vehicleLayer.currentIndex
                }
                DeviationLayer {
                    objectName: "deviationLayer"
                    anchors.fill: parent
                    map: pane.map
                    visible: page.replaying
                    model: page.comparison.track
                }
                PhotoLayer {
                    objectName: "photoLayer"
                    anchors.fill: parent
                    map: pane.map
                    visible: page.replaying
                    survey: page.photos
                }
                TrafficLayer {
                    objectName: "trafficLayer"
                    anchors.fill: parent
                    map: pane.map
                    traffic: page.traffic
                    imperial: page.units.imperial
                    labelsBelow: zoneLayer
                    enabled: false // clicks are for the vehicles
                }
                VehicleLayer {
                    id: vehicleLayer
                    objectName: "vehicleLayer"
                    anchors.fill: parent
                    map: pane.map
                    model: page.vehicleModel
                    labelsBelow: zoneLayer
                    autoFit: true // the fleet framed as it reports, until the operator moves the map
                }
                Row {
                    objectName: "flyMapControls"
                    anchors.left: parent.left
                    anchors.top: parent.top
                    anchors.leftMargin: pane.controlsLeft
                    anchors.topMargin: pane.controlsTop
                    spacing: 4
                    Button {
                        objectName: "fitAllButton"
                        text: qsTr("Fit all")
                        focusPolicy: Qt.NoFocus
                        enabled: vehicleLayer.positionedCount > 0
                        onClicked: vehicleLayer.fitToMap()
                        ToolTip.visible: hovered
                        ToolTip.text: qsTr("Show every vehicle on the map")
                    }
                    Button {
                        objectName: "followButton"
                        text: qsTr("Follow")
                        checkable: true
                        focusPolicy: Qt.NoFocus
                        enabled: vehicleLayer.currentIndex >= 0
                        checked: vehicleLayer.follow
                        onToggled: vehicleLayer.follow = checked
                        ToolTip.visible: hovered
                        ToolTip.text: qsTr("Keep the chosen vehicle in the middle of the map")
                    }
                    Button {
                        objectName: "videoButton"
                        text: qsTr("Video")
                        checkable: true
                        checked: true
                        focusPolicy: Qt.NoFocus
                        visible: page.video !== null
                        onToggled: videoPanel.shownByOperator = checked
                        ToolTip.visible: hovered
                        ToolTip.text: qsTr("Show the chosen vehicle's video over the map")
                    }
                }
                Connections {
                    target: page.replay
                    function onSeeked() { vehicleLayer.clearTrails() }
                    function onLoadedChanged() { vehicleLayer.clearTrails() }
                }
                Connections {
                    target: pane.map
                    function onClicked(coordinate, modifiers) {
                        if (commands.goMode && page.current)
                            commands.confirm(qsTr("Fly %1 to %2?").arg(page.current.name).arg(page.units.formatCoordinate(coordinate)),
                                             () => { page.fleet.goTo(vehicleLayer.currentIndex, coordinate.latitude, coordinate.longitude); commands.goMode = false })
                    }
                }
            }
            VideoPanel {
                id: videoPanel
                property bool shownByOperator: true
                theme: page.theme
                video: page.video
                vehicle: visible ? page.current : null
                visible: page.video !== null && page.current !== null && !page.replaying && shownByOperator
                x: swapped ? 0 : mapArea.width - width - 8
                y: swapped ? 0 : mapArea.height - height - 26  // above the map's attribution
                width: swapped ? mapArea.width : Math.min(implicitWidth, mapArea.width / 2)
                height: swapped ? mapArea.height : Math.min(implicitHeight, mapArea.height / 2)
                z: 1
            }
            }
            // Every in-flight alert, most urgent first within each: the battery's advice (amber,
            // then red, with Return home behind the command bar's confirmation), two of ours or
            // one of ours and an aircraft predicted to come too close, a vehicle predicted to enter
            // a zone or leave its fence. Each also went into the command log as it rose.
            AlertBanner {
                theme: page.theme
                objectName: "alertBanner"
                Layout.fillWidth: true
                monitors: [advisory, page.proximity, page.zoneAlerts]
                hidden: page.replaying
                canReturnHome: page.current !== null
                onReturnHomeRequested: {
                    const v = page.current
                    commands.confirm(advisory.returnHomeQuestion, () => page.fleet.commands.send(CommandPolicy.ReturnHome, v))
                }
            }
            ResumePanel {
                objectName: "resumePanel"
                Layout.fillWidth: true
                theme: page.theme
                resume: page.resume
            }
            Binding {
                target: page.resume
                when: page.resume !== null
                property: "vehicle"
                value: page.replaying ? null : page.current
            }
            CommandBar {
                id: commands
                Layout.fillWidth: true
                theme: page.theme
                vehicle: page.current
                fleet: page.fleet
                preflight: page.replaying ? null : page.preflight
                gamepads: page.replaying ? null : page.gamepads
            }
            ReplayTimeline {
                theme: page.theme
                objectName: "replayTimeline"
                Layout.fillWidth: true
                replay: page.replay
                serverHistory: page.serverHistory
                photos: page.photos
                units: page.units
                vehicleIndex: vehicleLayer.currentIndex
            }
            Loader {
                objectName: "comparisonPanelLoader"
                Layout.fillWidth: true
                active: page.replaying
                sourceComponent: ComparisonPanel {
                    theme: page.theme
                    comparison: page.comparison
                    vehicleIndex: vehicleLayer.currentIndex
                }
            }
        }
        ColumnLayout {
            SplitView.preferredWidth: 320
            SplitView.minimumWidth: 240
            spacing: 4
            InstrumentPanel {
                theme: page.theme
                objectName: "instrumentPanel"
                Layout.fillWidth: true
                vehicle: page.visible ? page.current : null // hidden, its texts would still cost frames
                units: page.units
                advisory: advisory
            }
            // The plot: pick fields (each its own colour; another unit gets its own axis), or
            // compare the same field across every vehicle.
            RowLayout {
                Layout.fillWidth: true
                spacing: 4
                ComboBox {
                    id: fieldPicker
                    objectName: "plotFieldPicker"
                    Layout.fillWidth: true
                    // Named for the operator; what plotFields holds is the field's key at the same index.
                    model: plot.fieldTitles
                    readonly property string chosenField: currentIndex >= 0 ? plot.availableFields()[currentIndex] : ""
                    // Read with the model, so that a re-worded model (a language change) chooses it again.
                    currentIndex: model.length > 0 ? Math.max(0, plot.availableFields().indexOf("groundSpeed")) : -1
                }
                Button {
                    objectName: "plotAddButton"
                    text: qsTr("Add")
                    enabled: page.plotFields.indexOf(fieldPicker.chosenField) < 0
                    onClicked: page.plotFields = page.plotFields.concat([fieldPicker.chosenField])
                    ToolTip.visible: hovered
                    ToolTip.text: qsTr("Plot this field too")
                }
            }
            Flow {
                objectName: "plotFieldChips"
                Layout.fillWidth: true
                spacing: 4
                Repeater {
                    model: page.plotFields
                    delegate: Button {
                        required property string modelData
                        // plot.fieldTitles is read here so that a language change re-words the chip.
                        text: plot.fieldTitles[plot.availableFields().indexOf(modelData)] + "  ×"
                        flat: true
                        font.pixelSize: 11
                        padding: 4
                        enabled: page.plotFields.length > 1
                        onClicked: page.plotFields = page.plotFields.filter(f => f !== modelData)
                        ToolTip.visible: hovered
                        ToolTip.text: qsTr("Remove from the plot")
                    }
                }
                CheckBox {
                    objectName: "plotCompareCheck"
                    text: qsTr("All vehicles")
                    font.pixelSize: 11
                    padding: 2
                    checked: plot.compare
                    onToggled: plot.compare = checked
                    ToolTip.visible: hovered
                    ToolTip.text: qsTr("Compare these fields across every vehicle")
                }
                // Here rather than beside the field picker: that row keeps its width for a field's
                // name, which a longer language lengthens.
                ComboBox {
                    id: windowPicker
                    objectName: "plotWindowPicker"
                    implicitContentWidthPolicy: ComboBox.WidestText
                    model: [qsTr("1 min"), qsTr("5 min"), qsTr("30 min")]
                    currentIndex: 1
                }
            }
            TelemetryPlot {
                id: plot
                objectName: "telemetryPlot"
                Layout.fillWidth: true
                Layout.fillHeight: true
                Layout.minimumHeight: 140
                vehicle: page.current
                fleet: page.vehicleModel
                fields: page.plotFields
                windowSeconds: page.replaying ? page.replay.spanSeconds : [60, 300, 1800][windowPicker.currentIndex]
                textColor: page.palette.windowText
            }
            CommandLogView {
                theme: page.theme
                Layout.fillWidth: true
                Layout.preferredHeight: 150
                log: page.fleet.commandLog
            }
        }
    }
}
