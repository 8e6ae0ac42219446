import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Commands to the chosen vehicle. The ones where a mistake is dangerous ask first; each one's
// result shows beside the bar. `goMode` is on while the operator picks a point on the map.
ToolBar {
    id: bar
    required property Vehicle vehicle      // null: none chosen
    required property VehicleFleet fleet   // null: no client layer
    property bool goMode: false
    property var pending: null

    function confirm(question, action) {
        bar.pending = action
        confirmDialog.text = question
        confirmDialog.open()
    }

    Dialog {
        id: confirmDialog
        objectName: "commandConfirmDialog"
        property alias text: question.text
        title: qsTr("Are you sure?")
        modal: true
        parent: Overlay.overlay
        anchors.centerIn: parent
        standardButtons: Dialog.Yes | Dialog.No
        width: 420
        Label { id: question; wrapMode: Text.Wrap; width: confirmDialog.availableWidth }
        onAccepted: if (bar.pending) { bar.pending(); bar.pending = null }
        onRejected: bar.pending = null
    }

    ColumnLayout {
      anchors.left: parent.left
      anchors.right: parent.right
      spacing: 2
      Flow {
        Layout.fillWidth: true
        spacing: 4
        enabled: bar.vehicle !== null
        Button { objectName: "armButton"; text: qsTr("Arm"); onClicked: bar.confirm(qsTr("Arm %1? Its motors may start.").arg(bar.vehicle.name), () => bar.vehicle.arm()) }
        Button { objectName: "disarmButton"; text: qsTr("Disarm"); onClicked: bar.confirm(qsTr("Disarm %1? In the air it would fall.").arg(bar.vehicle.name), () => bar.vehicle.disarm()) }
        Button { objectName: "takeoffButton"; text: qsTr("Take off"); onClicked: bar.confirm(qsTr("Take off with %1 to 10 m?").arg(bar.vehicle.name), () => bar.vehicle.takeoff(10)) }
        Button { objectName: "autoButton"; text: qsTr("Auto"); onClicked: bar.vehicle.setMode("Auto")
                 ToolTip.visible: hovered; ToolTip.text: qsTr("Fly the uploaded mission") }
        Button { objectName: "pauseButton"; text: qsTr("Pause"); onClicked: bar.vehicle.setMode("Hold") }
        Button { objectName: "resumeButton"; text: qsTr("Resume"); onClicked: bar.vehicle.setMode("Auto") }
        Button { objectName: "landButton"; text: qsTr("Land"); onClicked: bar.confirm(qsTr("Land %1 where it is?").arg(bar.vehicle.name), () => bar.vehicle.land()) }
        Button { objectName: "homeButton"; text: qsTr("Return home"); onClicked: bar.confirm(qsTr("Send %1 home?").arg(bar.vehicle.name), () => bar.vehicle.returnHome()) }
        Button {
            objectName: "goButton"
            text: qsTr("Go here…")
            checkable: true
            checked: bar.goMode
            onToggled: bar.goMode = checked
            ToolTip.visible: hovered
            ToolTip.text: qsTr("Then click on the map where the vehicle should fly")
        }
      }
      Label {
          objectName: "commandResult"
          Layout.fillWidth: true
          elide: Text.ElideRight
          text: bar.fleet ? bar.fleet.commandResult : qsTr("Choose a vehicle on the map or in the list.")
      }
    }
}
