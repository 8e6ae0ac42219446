import QtQuick
import QtQuick.Controls
import QtQuick.Shapes
import Sortie.Ui

// What the zones' colours mean, shown while geographical zones (ED-269, ED-318) are loaded: their
// restriction, and a dashed outline for a zone that is not in force while the route flies.
Rectangle {
    id: legend
    required property Theme theme
    required property Airspace airspace
    objectName: "zoneLegend"
    visible: airspace.hasGeographicalZones
    color: theme.overlay
    radius: 3
    implicitWidth: rows.implicitWidth + 12
    implicitHeight: rows.implicitHeight + 8

    Column {
        id: rows
        anchors.centerIn: parent
        spacing: 2
        Repeater {
            model: [
                { colour: legend.theme.mapExclusion, text: qsTr("Prohibited"), dashed: false },
                { colour: legend.theme.mapAuthorisation, text: qsTr("Authorisation needed"), dashed: false },
                { colour: legend.theme.mapConditional, text: qsTr("Conditions apply"), dashed: false },
                { colour: legend.theme.mapInformation, text: qsTr("Information only"), dashed: false },
                { colour: legend.theme.mapExclusion, text: qsTr("Not in force during the flight"), dashed: true }
            ]
            delegate: Row {
                required property var modelData
                spacing: 6
                Item {
                    width: 16
                    height: 12
                    anchors.verticalCenter: parent.verticalCenter
                    Rectangle {
                        anchors.fill: parent
                        visible: !modelData.dashed
                        color: Qt.rgba(modelData.colour.r, modelData.colour.g, modelData.colour.b, 0.25)
                        border.color: modelData.colour
                        border.width: 2
                    }
                    Shape {
                        anchors.fill: parent
                        visible: modelData.dashed
                        ShapePath {
                            strokeColor: modelData.colour
                            strokeWidth: 2
                            strokeStyle: ShapePath.DashLine
                            dashPattern: [2, 2]
                            fillColor: "transparent"
                            startX: 1; startY: 1
                            PathLine { x: 15; y: 1 }
                            PathLine { x: 15; y: 11 }
                            PathLine { x: 1; y: 11 }
                            PathLine { x: 1; y: 1 }
                        }
                    }
                }
                Label {
                    textFormat: Text.PlainText
                    text: modelData.text
                    color: legend.theme.overlayText
                    font.pixelSize: legend.theme.smallFontSize
                }
            }
        }
    }
}
