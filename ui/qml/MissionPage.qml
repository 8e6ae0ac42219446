import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Mission edit: the route on the map beside its table. `routeModel` is any list model with
// latitude and longitude roles; `selectionModel` selects its rows.
Page {
    id: page
    property alias map: pane.map
    property alias routeLayer: routeLayer
    property alias areaLayer: areaLayer
    property alias pane: pane
    property var routeModel: null
    property var selectionModel: null
    property var areaPolygonModel: null
    property var areaTransectModel: null
    property bool editable: false
    property DisplayUnits units
    property string mapSource: "offline"
    property string tileUrlTemplate: ""
    property string mbtilesFile: ""
    property bool dark: false

    SplitView {
        anchors.fill: parent
        MapPane {
            id: pane
            SplitView.fillWidth: true
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
                editable: page.editable
            }
            RouteLayer {
                id: routeLayer
                objectName: "routeLayer"
                anchors.fill: parent
                map: pane.map
                model: page.routeModel
                selectionModel: page.selectionModel
                editable: page.editable
            }
        }
        Pane {
            SplitView.preferredWidth: 340
            SplitView.minimumWidth: 220
            ColumnLayout {
                anchors.fill: parent
                Label {
                    text: qsTr("Route")
                    font.bold: true
                    font.pixelSize: 16
                }
                Label {
                    objectName: "routeSummary"
                    text: page.routeModel ? qsTr("%n waypoint(s)", "", routeLayer.count) : qsTr("No route open. Log in to open a mission.")
                    wrapMode: Text.Wrap
                    Layout.fillWidth: true
                }
                ListView {
                    objectName: "waypointList"
                    Layout.fillWidth: true
                    Layout.fillHeight: true
                    clip: true
                    model: page.routeModel
                    delegate: ItemDelegate {
                        required property int index
                        required property double latitude
                        required property double longitude
                        width: ListView.view.width
                        text: (index + 1) + "  " + (page.units ? page.units.formatLatLon(latitude, longitude) : "")
                    }
                    ScrollBar.vertical: ScrollBar {}
                }
            }
        }
    }
}
