import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Commands to the chosen vehicle, or to the group when vehicles are ticked in the list. The ones
// where a mistake is dangerous ask first (the policy says which; a group command always asks, once,
// naming every vehicle); each one's result shows beside the bar. `goMode` is on while the operator
// picks a point on the map.
ToolBar {
    id: bar
    required property Vehicle vehicle      // null: none chosen
    required property VehicleFleet fleet
    property bool goMode: false
    property var pending: null

    // Which commands ask, what they ask and with what arguments they go: the fleet's CommandPolicy.
    readonly property CommandPolicy policy: bar.fleet.commands
    readonly property VehicleGroup group: bar.fleet.group
    readonly property bool toGroup: bar.group.count > 0
    function command(which) {   // a CommandPolicy.Command
        if (bar.toGroup) {
            bar.confirm(bar.group.confirmation(which), () => bar.group.send(which))
            return
        }
        if (!bar.vehicle)
            return
        if (bar.policy.needsConfirmation(which, bar.vehicle))
            bar.confirm(bar.policy.confirmation(which, bar.vehicle), () => bar.policy.send(which, bar.vehicle))
        else
            bar.policy.send(which, bar.vehicle)
    }

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
        Label { textFormat: Text.PlainText; id: question; wrapMode: Text.Wrap; width: confirmDialog.availableWidth }
        onAccepted: if (bar.pending) { bar.pending(); bar.pending = null }
        onRejected: bar.pending = null
    }

    ColumnLayout {
      anchors.left: parent.left
      anchors.right: parent.right
      spacing: 2
      RowLayout {
        objectName: "groupHeader"
        visible: bar.toGroup
        Layout.fillWidth: true
        Label {
            textFormat: Text.PlainText
            objectName: "groupTargets"
            Layout.fillWidth: true
            elide: Text.ElideRight
            font.bold: true
            text: qsTr("To %n ticked vehicle(s): %1", "", bar.group.count).arg(bar.group.names.join(", "))
        }
        Button { objectName: "groupClearButton"; text: qsTr("Untick all"); flat: true; onClicked: bar.group.clear() }
      }
      Flow {
        Layout.fillWidth: true
        spacing: 4
        enabled: bar.vehicle !== null || bar.toGroup
        Button { objectName: "armButton"; text: qsTr("Arm"); onClicked: bar.command(CommandPolicy.Arm) }
        Button { objectName: "disarmButton"; text: qsTr("Disarm"); onClicked: bar.command(CommandPolicy.Disarm) }
        Button { objectName: "takeoffButton"; text: qsTr("Take off"); onClicked: bar.command(CommandPolicy.TakeOff)
                 ToolTip.visible: hovered
                 ToolTip.text: bar.vehicle ? qsTr("Climb to %1 m above home").arg(bar.policy.takeoffAltitude(bar.vehicle)) : "" }
        Button { objectName: "autoButton"; text: qsTr("Auto"); onClicked: bar.command(CommandPolicy.Auto)
                 ToolTip.visible: hovered; ToolTip.text: qsTr("Fly the uploaded mission") }
        Button { objectName: "pauseButton"; text: qsTr("Pause"); onClicked: bar.command(CommandPolicy.Hold) }
        Button { objectName: "resumeButton"; text: qsTr("Resume"); onClicked: bar.command(CommandPolicy.Auto) }
        Button { objectName: "landButton"; text: qsTr("Land"); onClicked: bar.command(CommandPolicy.Land) }
        Button { objectName: "homeButton"; text: qsTr("Return home"); onClicked: bar.command(CommandPolicy.ReturnHome) }
        Button {
            objectName: "goButton"
            text: qsTr("Go here…")
            checkable: true
            enabled: !bar.toGroup
            checked: bar.goMode
            onToggled: bar.goMode = checked
            ToolTip.visible: hovered
            ToolTip.text: qsTr("Then click on the map where the vehicle should fly")
        }
      }
      Label {
          textFormat: Text.PlainText
          objectName: "commandResult"
          Layout.fillWidth: true
          elide: Text.ElideRight
          text: bar.toGroup && bar.group.result.length > 0 ? bar.group.result
                : bar.fleet.commandResult.length > 0 ? bar.fleet.commandResult
                : qsTr("Choose a vehicle on the map or in the list; tick several to command them together.")
      }
    }
}
