import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Every route given to a vehicle (FleetRoutes), beside the map: the route, its vehicle with the
// vehicle's colour, where it stands (planned, uploaded, flying: waypoint n of m, flown) and its
// times. Only binds to the model's roles; times are formatted by DisplayUnits ("—" when unknown).
ColumnLayout {
    id: list
    required property Theme theme
    required property FleetRoutes routes
    required property DisplayUnits units
    // The chosen vehicle's row in the fleet (-1: none): its routes are highlighted.
    property int currentVehicleRow: -1
    spacing: 2

    Label {
        textFormat: Text.PlainText
        text: qsTr("Routes")
        font.bold: true
        font.pixelSize: 16
    }
    ListView {
        id: view
        objectName: "fleetRoutesView"
        Layout.fillWidth: true
        Layout.fillHeight: true
        implicitHeight: contentHeight
        clip: true
        boundsBehavior: Flickable.StopAtBounds
        model: list.routes
        // Shown only when the rows do not fit (more than the room the page gives the list).
        readonly property bool overflowing: contentHeight > height + 1
        ScrollBar.vertical: ScrollBar { policy: view.overflowing ? ScrollBar.AlwaysOn : ScrollBar.AlwaysOff }
        delegate: Item {
            id: row
            required property int index
            required property string routeName
            required property string vehicleName
            required property int vehicleRow
            required property color color
            required property string stateText
            required property double flightSeconds
            required property double elapsedSeconds
            required property double remainingSeconds
            objectName: "fleetRouteRow" + index
            width: ListView.view.width
            implicitHeight: lines.implicitHeight + 8
            Rectangle {
                // The chosen vehicle's routes.
                anchors.fill: parent
                visible: row.vehicleRow >= 0 && row.vehicleRow === list.currentVehicleRow
                color: Qt.rgba(list.palette.highlight.r, list.palette.highlight.g, list.palette.highlight.b, 0.25)
            }
            RowLayout {
                anchors.fill: parent
                anchors.margins: 4
                anchors.rightMargin: view.overflowing ? 14 : 4 // clear of the scroll bar
                spacing: 6
                Rectangle {
                    objectName: "swatch"
                    Layout.alignment: Qt.AlignTop
                    Layout.topMargin: 3
                    implicitWidth: 12
                    implicitHeight: 12
                    radius: 6
                    color: row.color
                    border.color: list.theme.base
                }
                ColumnLayout {
                    id: lines
                    Layout.fillWidth: true
                    spacing: 0
                    Label {
                        textFormat: Text.PlainText
                        objectName: "routeName"
                        Layout.fillWidth: true
                        text: row.routeName
                        font.bold: true
                        elide: Text.ElideRight
                    }
                    // The vehicle, then where the route stands; the state moves to a line of its
                    // own rather than breaking ("waypoint 3 of 7" stays whole).
                    Flow {
                        id: stateLine
                        Layout.fillWidth: true
                        spacing: 0
                        Label {
                            textFormat: Text.PlainText
                            objectName: "routeVehicle"
                            text: row.vehicleName
                            font.pixelSize: 12
                        }
                        Label {
                            textFormat: Text.PlainText
                            text: "  ·  "
                            font.pixelSize: 12
                        }
                        Label {
                            textFormat: Text.PlainText
                            objectName: "routeState"
                            text: row.stateText
                            width: Math.min(implicitWidth, stateLine.width)
                            elide: Text.ElideRight
                            font.pixelSize: 12
                        }
                    }
                    Label {
                        textFormat: Text.PlainText
                        objectName: "routeTimes"
                        Layout.fillWidth: true
                        text: isNaN(row.elapsedSeconds)
                              ? qsTr("%1 flight").arg(list.units.formatDuration(row.flightSeconds))
                              : qsTr("%1 flight · %2 flown · %3 left").arg(list.units.formatDuration(row.flightSeconds))
                                                                     .arg(list.units.formatDuration(row.elapsedSeconds))
                                                                     .arg(list.units.formatDuration(row.remainingSeconds))
                        wrapMode: Text.Wrap
                        font.pixelSize: 12
                        opacity: 0.8
                    }
                }
            }
        }
    }
}
