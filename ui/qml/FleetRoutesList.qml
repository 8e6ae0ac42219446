import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Every route given to a vehicle (FleetRoutes), beside the map: the route, its vehicle with the
// vehicle's colour, where it stands (planned, uploaded, flying: waypoint n of m, flown) and its
// times. Only binds to the model's roles; times are formatted by DisplayUnits ("—" when unknown).
ColumnLayout {
    id: list
    required property FleetRoutes routes
    required property DisplayUnits units
    // The chosen vehicle's row in the fleet (-1: none): its routes are highlighted.
    property int currentVehicleRow: -1
    spacing: 2

    Label {
        text: qsTr("Routes")
        font.bold: true
        font.pixelSize: 16
    }
    ListView {
        id: view
        objectName: "fleetRoutesView"
        Layout.fillWidth: true
        Layout.fillHeight: true
        Layout.preferredHeight: contentHeight
        Layout.minimumHeight: Math.min(contentHeight, 60)
        clip: true
        boundsBehavior: Flickable.StopAtBounds
        model: list.routes
        ScrollBar.vertical: ScrollBar { policy: view.contentHeight > view.height ? ScrollBar.AlwaysOn : ScrollBar.AsNeeded }
        delegate: Rectangle {
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
            color: vehicleRow >= 0 && vehicleRow === list.currentVehicleRow
                   ? Qt.rgba(list.palette.highlight.r, list.palette.highlight.g, list.palette.highlight.b, 0.25) : "transparent"
            RowLayout {
                anchors.fill: parent
                anchors.margins: 4
                spacing: 6
                Rectangle {
                    objectName: "swatch"
                    Layout.alignment: Qt.AlignTop
                    Layout.topMargin: 3
                    implicitWidth: 12
                    implicitHeight: 12
                    radius: 6
                    color: row.color
                    border.color: "white"
                }
                ColumnLayout {
                    id: lines
                    Layout.fillWidth: true
                    spacing: 0
                    Label {
                        objectName: "routeName"
                        Layout.fillWidth: true
                        text: row.routeName
                        font.bold: true
                        elide: Text.ElideRight
                    }
                    Label {
                        objectName: "routeState"
                        Layout.fillWidth: true
                        text: row.vehicleName + "  ·  " + row.stateText
                        wrapMode: Text.Wrap
                        font.pixelSize: 12
                    }
                    Label {
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
