import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Live telemetry: vehicles on the map, turned to their heading, with trails and homes.
// `vehicleModel` is any list model with the roles VehicleLayer reads.
Page {
    id: page
    property alias map: pane.map
    property alias vehicleLayer: vehicleLayer
    property alias pane: pane
    property var vehicleModel: null
    property DisplayUnits units
    property string mapSource: "offline"
    property string tileUrlTemplate: ""
    property string mbtilesFile: ""
    property bool dark: false

    SplitView {
        anchors.fill: parent
        Pane {
            SplitView.preferredWidth: 260
            SplitView.minimumWidth: 180
            ColumnLayout {
                anchors.fill: parent
                Label {
                    text: qsTr("Vehicles")
                    font.bold: true
                    font.pixelSize: 16
                }
                Label {
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
                    delegate: ItemDelegate {
                        required property int index
                        required property var model
                        width: ListView.view.width
                        highlighted: ListView.isCurrentItem
                        text: model.name !== undefined ? model.name : qsTr("Vehicle %1").arg(index + 1)
                        onClicked: vehicleLayer.currentIndex = index
                    }
                }
            }
        }
        MapPane {
            id: pane
            SplitView.fillWidth: true
            units: page.units
            mapSource: page.mapSource
            tileUrlTemplate: page.tileUrlTemplate
            mbtilesFile: page.mbtilesFile
            dark: page.dark
            VehicleLayer {
                id: vehicleLayer
                objectName: "vehicleLayer"
                anchors.fill: parent
                map: pane.map
                model: page.vehicleModel
            }
        }
    }
}
