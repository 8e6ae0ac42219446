import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import QtQml.Models
import Sortie.Ui

// Mission edit: the route on the map beside its panel and table. Every gesture becomes an undoable
// edit of the document of `missions` (the client's MissionController).
Page {
    id: page
    property alias map: pane.map
    property alias routeLayer: routeLayer
    property alias theirRouteLayer: theirRouteLayer
    property alias areaLayer: areaLayer
    property alias pane: pane
    property alias panel: panel
    required property DisplayUnits units
    // The client's services (core's ClientGraph); the page takes what it uses from it.
    required property ClientGraph graph
    readonly property MissionController missions: graph.missions
    readonly property RouteDocument doc: missions.document
    // The models the layers and the table draw.
    readonly property AbstractItemModel routeModel: doc.model
    readonly property ItemSelectionModel selectionModel: doc.selection
    readonly property AbstractItemModel vehicleModel: graph.fleet // the fleet: where the vehicles are while planning
    property string tool: ""               // "", "scan" (an area-scan figure), "zonePolygon", "zoneCircle" or "offlineArea"
    property string mapSource: "offline"
    property string tileUrlTemplate: ""
    property string mbtilesFile: ""
    property string orthophotoFile: ""
    property real orthophotoOpacity: 0.8
    property string tilePackFile: ""    // the web source's offline pack (OfflineMaps.packFile)
    property bool tilesCacheOnly: false // the web source never uses the network
    property bool show3d: false          // the map's place taken by the 3D view
    onShow3dChanged: {
        if (show3d)
            view3d.setSource("Scene3DView.qml", { document: page.doc, fleetRoutes: page.fleetRoutes, airspace: page.airspace,
                                                  elevation: page.elevation, theme: page.theme })
        else
            view3d.source = ""
    }
    required property Theme theme
    readonly property ElevationService elevation: graph.elevation   // the terrain, for the profile
    readonly property RouteEndurance endurance: graph.endurance     // will the battery last: figures, changes, point of no return
    readonly property Traffic traffic: graph.traffic                // manned traffic around (ADS-B)
    readonly property FleetRoutes fleetRoutes: graph.fleetRoutes    // every route given to a vehicle: on the map and in a list beside it
    readonly property RouteDeconfliction deconfliction: graph.deconfliction // the open route's conflicts with them; null without vehicles
    readonly property Airspace airspace: graph.airspace             // the zones: on the map, in the zone panel, on the profile
    readonly property ZoneSharing zoneSharing: graph.zoneSharing    // the zone panel's server actions
    readonly property ZoneFeed zoneFeed: graph.zoneFeed             // published zone files fetched from a URL
    property alias zoneLayer: zoneLayer
    property alias zonePanel: zonePanel
    // Ctrl+Z goes to the zone editor while the zone panel is open (zones are not part of the route).
    readonly property bool zoneEditing: zonePanel.visible
    // The tools that click a polygon's corners into polygonDraft: a zone, or an offline maps area.
    readonly property bool drawingPolygon: tool === "zonePolygon" || tool === "offlineArea"
    property var offlineArea: []   // the offline maps area (QGeoCoordinate corners), shown while it is chosen

    // The offline maps area, drawn with the zones' polygon tool (or Shift+drag for a rectangle);
    // what is drawn goes out through these signals: the page does not choose areas itself.
    signal areaDrawn(var corners)
    signal areaRectangleDrawn(var corner, var opposite)
    signal areaDrawingCancelled()
    function drawArea() { polygonDraft.clear(); page.tool = "offlineArea" }
    function finishArea() {
        const corners = polygonDraft.coordinates()
        polygonDraft.clear()
        page.tool = ""
        page.areaDrawn(corners)
    }
    function cancelArea() { polygonDraft.clear(); page.tool = ""; page.areaDrawingCancelled() }

    // The segment being drawn ("scan" draws the first of the editor's tools, the area scan).
    property int drawingTool: 0
    readonly property drawingTool currentTool: doc.editor.drawingTool(drawingTool)

    function finishScan() {
        if (page.currentTool.valid && scanDraft.count >= page.currentTool.minimumPoints)
            page.doc.editor.addSegment(page.currentTool.algorithm, scanDraft.coordinates())
        scanDraft.clear()
        page.tool = ""
    }

    CoordinateListModel { id: scanDraft }
    CoordinateListModel { id: polygonDraft }   // the corners of a zone (or an offline area) being drawn

    function finishZone() {
        page.airspace.editor.addPolygon(polygonDraft.coordinates())
        polygonDraft.clear()
        page.tool = ""
    }

    Connections {
        target: page.missions
        function onRouteOpened() { if (routeLayer.count > 0) routeLayer.fitToMap(60) }
    }

    SplitView {
        anchors.fill: parent
        // The map over the terrain profile of the route.
        SplitView {
        orientation: Qt.Vertical
        SplitView.fillWidth: true
        MapPane {
            id: pane
            SplitView.fillWidth: true
            SplitView.fillHeight: true
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
                // Zones under everything else: exclusion hatched red, inclusion outlined green.
                id: zoneLayer
                objectName: "missionZoneLayer"
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
                ZoneLegend {
                    // Above the scale bar.
                    theme: page.theme
                    airspace: page.airspace
                    anchors.left: parent.left
                    anchors.bottom: parent.bottom
                    anchors.leftMargin: pane.controlsLeft
                    anchors.bottomMargin: 44
                }
            }
            FleetRoutesLayer {
                // The other vehicles' routes, in their colours; the open one is the editor's (hideOpen).
                objectName: "missionFleetRoutesLayer"
                anchors.fill: parent
                map: pane.map
                model: page.fleetRoutes
                hideOpen: true
            }
            TrafficLayer {
                objectName: "missionTrafficLayer"
                anchors.fill: parent
                map: pane.map
                traffic: page.traffic
                imperial: page.units.imperial
                labelsBelow: zoneLayer
                enabled: false // clicks are for the route
            }
            VehicleLayer {
                // Where the vehicles are, for planning near them; the map opens framed on them
                // until a route is opened (which frames the route) or the operator moves the map.
                id: vehicleLayer
                objectName: "missionVehicleLayer"
                anchors.fill: parent
                map: pane.map
                model: page.vehicleModel
                labelsBelow: zoneLayer
                enabled: false // clicks are for the route
                autoFit: true
            }
            AreaScanLayer {
                objectName: "scanDraftLayer"
                anchors.fill: parent
                map: pane.map
                polygonModel: scanDraft
                closed: page.currentTool.closed
                color: page.theme.mapDraft
                editable: page.tool === "scan"
                onVertexMoved: (index, coordinate, step) => scanDraft.setCoordinate(index, coordinate.latitude, coordinate.longitude)
            }
            RouteLayer {
                // The server's copy during a conflict: a read-only ghost under ours.
                id: theirRouteLayer
                objectName: "theirRouteLayer"
                anchors.fill: parent
                map: pane.map
                visible: page.missions.conflict
                model: page.missions.conflictDetails.theirs
                color: page.theme.mapGhost
                opacity: 0.75
                editable: false
            }
            RouteLayer {
                id: routeLayer
                objectName: "routeLayer"
                anchors.fill: parent
                map: pane.map
                model: page.routeModel
                actionMarksRole: "actionMarks"
                selectionModel: page.selectionModel
                editable: page.tool === ""
                onWaypointsMoved: (rows, coordinates) => page.doc.editor.moveWaypoints(rows, coordinates)
                onLegClicked: (leg, coordinate, modifiers) => page.doc.editor.insertWaypoint(leg + 1, coordinate)
            }
            ZoneCrossingLayer {
                // The stretches of the route inside a zone (the issue list's airspace errors), red over the route.
                objectName: "zoneCrossingLayer"
                anchors.fill: parent
                map: pane.map
                enabled: false // clicks are for the route
                airspace: page.airspace
            }
            AreaScanLayer {
                id: areaLayer
                objectName: "areaLayer"
                anchors.fill: parent
                map: pane.map
                polygon: page.doc.scanPolygon
                path: page.doc.scanPath
                // The current segment's figure: drag a corner (the path follows), click an edge to add
                // one, right-click one to remove it, drag a circle's radius handle. Above the route:
                // its first point lies under the segment's own route marker, which cannot drag it.
                editable: page.tool === "" && page.doc.scanPolygon.length > 0
                onVertexMoved: (index, coordinate, step) => page.doc.editor.moveVertex(page.doc.currentRow, index, coordinate, step)
                onEdgeClicked: (index, coordinate, modifiers) => page.doc.editor.insertVertex(page.doc.currentRow, index + 1, coordinate)
                onVertexRemoveRequested: index => page.doc.editor.removeVertex(page.doc.currentRow, index)
                closed: page.doc.preview.figureType !== "polyline"
                radius: page.doc.preview.radius
                onRadiusMoved: (meters, step) => page.doc.editor.setRadius(page.doc.currentRow, meters, step)
            }
            AreaScanLayer {
                // The offline maps area while it is chosen: read only.
                objectName: "offlineAreaLayer"
                anchors.fill: parent
                map: pane.map
                visible: page.offlineArea.length > 0 && page.tool !== "offlineArea"
                enabled: false // clicks are for the route
                color: page.theme.mapRoute
                polygon: page.offlineArea
            }
            AreaScanLayer {
                // The chosen drawn zone's corners (a circle: its centre and radius handle) and the
                // corners of a polygon being drawn (a zone's red, an offline area's blue): drag a
                // corner, click an edge to add one, right-click to remove.
                objectName: "zoneEditLayer"
                anchors.fill: parent
                map: pane.map
                color: page.tool === "offlineArea" ? page.theme.mapRoute : page.theme.mapExclusion
                polygonModel: page.drawingPolygon ? polygonDraft : null
                polygon: page.drawingPolygon ? [] : page.airspace.editor.figure
                radius: page.drawingPolygon ? 0 : page.airspace.editor.radius
                editable: page.tool === "" && page.airspace.selectedCustom >= 0
                onVertexMoved: (index, coordinate, step) => page.airspace.editor.moveVertex(page.airspace.selectedCustom, index, coordinate, step)
                onEdgeClicked: (index, coordinate, modifiers) => page.airspace.editor.insertVertex(page.airspace.selectedCustom, index + 1, coordinate)
                onVertexRemoveRequested: index => page.airspace.editor.removeVertex(page.airspace.selectedCustom, index)
                onRadiusMoved: (meters, step) => page.airspace.editor.setRadius(page.airspace.selectedCustom, meters, step)
            }
            ConflictLayer {
                // Where the open route would meet another vehicle: both at the closest approach.
                objectName: "conflictLayer"
                anchors.fill: parent
                map: pane.map
                enabled: false // clicks are for the route
                deconfliction: page.deconfliction
            }
            EnduranceLayer {
                // Where the battery runs out: its changes and the point of no return.
                id: enduranceLayer
                objectName: "enduranceLayer"
                anchors.fill: parent
                map: pane.map
                enabled: false // clicks are for the route
                endurance: page.endurance
            }
            Connections {
                target: pane.map
                function onClicked(coordinate, modifiers) {
                    if (modifiers !== Qt.NoModifier)
                        return
                    if (page.drawingPolygon) {
                        polygonDraft.append(coordinate.latitude, coordinate.longitude)
                    } else if (page.tool === "zoneCircle") {
                        page.airspace.editor.addCircle(coordinate)
                        page.tool = ""
                    } else if (page.tool === "scan") {
                        scanDraft.append(coordinate.latitude, coordinate.longitude)
                        if (page.currentTool.oneClick)
                            page.finishScan() // one click places it
                    } else
                        page.doc.editor.addWaypoint(coordinate)
                }
                function onAreaSelected(rect, modifiers) {
                    if (page.tool !== "offlineArea") {
                        routeLayer.selectInRect(rect, modifiers)
                        return
                    }
                    polygonDraft.clear()
                    page.tool = ""
                    page.areaRectangleDrawn(pane.map.toCoordinate(Qt.point(rect.x, rect.y)),
                                           pane.map.toCoordinate(Qt.point(rect.x + rect.width, rect.y + rect.height)))
                }
            }
            ToolButton {
                objectName: "zonesButton"
                anchors.left: parent.left
                anchors.top: parent.top
                anchors.leftMargin: pane.controlsLeft
                anchors.topMargin: pane.controlsTop
                text: qsTr("Zones (%1)").arg(page.airspace.count)
                checkable: true
                checked: zonePanel.visible
                onToggled: zonePanel.visible = checked
                background: Rectangle { color: page.theme.overlay; radius: 3 }
            }
            ZonePanel {
                theme: page.theme
                routeEditor: page.doc.editor
                id: zonePanel
                objectName: "zonePanel"
                visible: false
                anchors.left: parent.left
                anchors.top: parent.top
                anchors.leftMargin: pane.controlsLeft
                anchors.topMargin: pane.controlsTop + 40
                width: 300
                height: Math.min(implicitHeight, parent.height - anchors.topMargin - 50)
                airspace: page.airspace
                sharing: page.zoneSharing
                feed: page.zoneFeed
                tool: page.tool
                draftCount: polygonDraft.count
                onToolRequested: tool => { polygonDraft.clear(); page.tool = tool }
                onFinishRequested: page.finishZone()
            }
            Frame {
                // Drawing the offline maps area (the Offline maps dialog comes back after).
                objectName: "offlineAreaBar"
                visible: page.tool === "offlineArea"
                anchors.top: parent.top
                anchors.horizontalCenter: parent.horizontalCenter
                anchors.topMargin: pane.controlsTop
                RowLayout {
                    Label { textFormat: Text.PlainText; text: qsTr("Click the corners (%1 so far), or Shift+drag a box").arg(polygonDraft.count) }
                    Button {
                        objectName: "finishAreaButton"
                        text: qsTr("Done")
                        enabled: polygonDraft.count >= 3
                        onClicked: page.finishArea()
                    }
                    Button {
                        objectName: "cancelAreaButton"
                        text: qsTr("Cancel")
                        onClicked: page.cancelArea()
                    }
                }
            }
            Frame {
                visible: page.tool === "scan"
                anchors.top: parent.top
                anchors.horizontalCenter: parent.horizontalCenter
                anchors.topMargin: pane.controlsTop
                RowLayout {
                    ComboBox {
                        objectName: "segmentToolPicker"
                        model: page.doc.editor.drawingToolNames
                        currentIndex: page.drawingTool
                        onActivated: index => { page.drawingTool = index; scanDraft.clear() }
                        Layout.preferredWidth: 170
                    }
                    Label {
                        textFormat: Text.PlainText
                        text: page.currentTool.hint(scanDraft.count)
                    }
                    Button {
                        objectName: "finishScanButton"
                        text: qsTr("Create")
                        enabled: page.currentTool.valid && scanDraft.count >= page.currentTool.minimumPoints
                        onClicked: page.finishScan()
                    }
                    Button {
                        text: qsTr("Cancel")
                        onClicked: { scanDraft.clear(); page.tool = "" }
                    }
                }
            }
            Loader {
                // The same route, selection and zones in 3D (ui/view3d, docs/view3d.md), over the map
                // while the operator wants it; loaded only then (Qt Quick 3D needs OpenGL).
                id: view3d
                objectName: "missionView3dLoader"
                anchors.fill: parent
                z: 50
                visible: page.show3d
                focus: page.show3d
            }
            RoundButton {
                // The 2D/3D switch, under the zoom buttons.
                objectName: "view3dSwitch"
                anchors.right: parent.right
                anchors.top: parent.top
                anchors.rightMargin: 10
                anchors.topMargin: pane.controlsTop + 100
                z: 51
                checkable: true
                checked: page.show3d
                text: page.show3d ? qsTr("2D") : qsTr("3D")
                focusPolicy: Qt.NoFocus
                onToggled: page.show3d = checked
                ToolTip.visible: hovered
                ToolTip.text: page.show3d ? qsTr("Back to the map") : qsTr("The route, the ground and the zones in 3D")
            }
        }
        TerrainProfilePanel {
            id: terrainProfile
            SplitView.preferredHeight: 170
            SplitView.minimumHeight: 90
            routeModel: page.routeModel
            selectionModel: page.selectionModel
            elevation: page.elevation
            airspace: page.airspace
            endurance: page.endurance
            theme: page.theme
        }
        }
        Pane {
            // Every route given to a vehicle, beside the map (once there is one).
            visible: page.fleetRoutes.count > 0
            SplitView.preferredWidth: 230
            SplitView.minimumWidth: 170
            FleetRoutesList {
                theme: page.theme
                objectName: "missionFleetRoutes"
                anchors.fill: parent
                routes: page.fleetRoutes
                units: page.units
            }
        }
        RoutePanel {
            theme: page.theme
            id: panel
            SplitView.preferredWidth: Math.max(460, panel.neededWidth)
            SplitView.minimumWidth: 320
            missions: page.missions
            doc: page.doc
            units: page.units
            routeModel: page.routeModel
            terrain: terrainProfile.profile
            endurance: page.endurance
            deconfliction: page.deconfliction
            airspace: page.airspace
            waypointCount: routeLayer.count
            scanning: page.tool === "scan"
            onScanToggled: on => page.tool = on ? "scan" : ""
        }
    }
}
