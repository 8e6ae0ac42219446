import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Mission edit: the route on the map beside its panel and table. With `missions` (the client's
// MissionController) every gesture becomes an undoable edit of its document; without one the
// page shows whatever list model `routeModel` is.
Page {
    id: page
    property alias map: pane.map
    property alias routeLayer: routeLayer
    property alias theirRouteLayer: theirRouteLayer
    property alias areaLayer: areaLayer
    property alias pane: pane
    property alias panel: panel
    property var missions: null
    readonly property var doc: missions ? missions.document : null
    property var routeModel: doc ? doc.model : null
    property var selectionModel: doc ? doc.selection : null
    property var areaPolygonModel: null
    property var areaTransectModel: null
    property bool editable: doc !== null
    property string tool: ""               // "" or "scan" (drawing an area-scan polygon)
    property DisplayUnits units
    property string mapSource: "offline"
    property string tileUrlTemplate: ""
    property string mbtilesFile: ""
    property bool dark: false
    property QtObject elevation: null       // the client's ElevationService, for the terrain profile

    function finishScan() {
        if (page.doc && scanDraft.count >= 3)
            page.doc.addAreaScan(scanDraft.coordinates())
        scanDraft.clear()
        page.tool = ""
    }

    CoordinateListModel { id: scanDraft }

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
            dark: page.dark
            AreaScanLayer {
                id: areaLayer
                objectName: "areaLayer"
                anchors.fill: parent
                map: pane.map
                polygonModel: page.areaPolygonModel
                transectModel: page.areaTransectModel
                polygon: page.doc ? page.doc.scanPolygon : []
                path: page.doc ? page.doc.scanPath : []
            }
            AreaScanLayer {
                objectName: "scanDraftLayer"
                anchors.fill: parent
                map: pane.map
                polygonModel: scanDraft
                color: "#ef6c00"
                editable: page.tool === "scan"
                onVertexMoved: (index, coordinate) => scanDraft.setCoordinate(index, coordinate.latitude, coordinate.longitude)
            }
            RouteLayer {
                // The server's copy during a conflict: a read-only ghost under ours.
                id: theirRouteLayer
                objectName: "theirRouteLayer"
                anchors.fill: parent
                map: pane.map
                visible: page.missions !== null && page.missions.conflict
                model: page.missions ? page.missions.conflictDetails.theirs : null
                color: "#8d8d8d"
                opacity: 0.75
                editable: false
            }
            RouteLayer {
                id: routeLayer
                objectName: "routeLayer"
                anchors.fill: parent
                map: pane.map
                model: page.routeModel
                selectionModel: page.selectionModel
                editable: page.editable && page.tool === ""
                onWaypointsMoved: (rows, coordinates) => page.doc.moveWaypoints(rows, coordinates)
                onLegClicked: (leg, coordinate, modifiers) => page.doc.insertWaypoint(leg, coordinate.latitude, coordinate.longitude)
            }
            Connections {
                target: pane.map
                function onClicked(coordinate, modifiers) {
                    if (!page.doc || modifiers !== Qt.NoModifier)
                        return
                    if (page.tool === "scan")
                        scanDraft.append(coordinate.latitude, coordinate.longitude)
                    else
                        page.doc.addWaypoint(coordinate.latitude, coordinate.longitude)
                }
                function onAreaSelected(rect, modifiers) { routeLayer.selectInRect(rect, modifiers) }
            }
            Frame {
                visible: page.tool === "scan"
                anchors.top: parent.top
                anchors.horizontalCenter: parent.horizontalCenter
                anchors.topMargin: 10
                RowLayout {
                    Label { text: qsTr("Click the corners of the area (%1 so far)").arg(scanDraft.count) }
                    Button {
                        objectName: "finishScanButton"
                        text: qsTr("Create scan")
                        enabled: scanDraft.count >= 3
                        onClicked: page.finishScan()
                    }
                    Button {
                        text: qsTr("Cancel")
                        onClicked: { scanDraft.clear(); page.tool = "" }
                    }
                }
            }
        }
        TerrainProfilePanel {
            id: terrainProfile
            visible: page.elevation !== null  // the client always has one ("none" at least)
            SplitView.preferredHeight: 170
            SplitView.minimumHeight: 90
            routeModel: page.routeModel
            selectionModel: page.selectionModel
            elevation: page.elevation
        }
        }
        RoutePanel {
            id: panel
            SplitView.preferredWidth: 460
            SplitView.minimumWidth: 320
            page: page
        }
    }
}
