import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Commands to the chosen vehicle, or to the group when vehicles are ticked in the list. The ones
// where a mistake is dangerous ask first (the policy says which; a group command always asks, once,
// naming every vehicle); each one's result shows beside the bar. `goMode` is on while the operator
// picks a point on the map. What the vehicle's pre-flight checklist holds back (the policy's
// blockers) is not sent: the operator sees why, and may send it anyway, which the command log and
// the flight log keep.
ToolBar {
    id: bar
    required property Theme theme
    required property Vehicle vehicle      // null: none chosen
    required property VehicleFleet fleet
    required property PreflightChecklists preflight   // null without vehicles
    required property GamepadCommands gamepads        // null without vehicles
    // The chosen vehicle's checklist (made on first use; asked again after the files are re-read).
    readonly property VehicleChecklist checklist: bar.preflight && bar.vehicle && bar.preflight.revision >= 0
                                                  ? bar.preflight.checklistFor(bar.vehicle) : null
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
        const held = bar.policy.blockers(which, bar.vehicle)
        if (held.length > 0) {
            overrideDialog.command = which
            overrideDialog.vehicle = bar.vehicle
            overrideDialog.reasons = held
            overrideDialog.open()
            return
        }
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

    // A gamepad's button asks as the bar's own button would: the checklist and the question first.
    Connections {
        target: bar.gamepads
        function onCommandRequested(command) { bar.command(command) }
    }

    // A command the checklist holds back: why, and the operator's choice to send it anyway.
    Dialog {
        id: overrideDialog
        objectName: "checklistOverrideDialog"
        property int command: CommandPolicy.Arm
        property Vehicle vehicle: null
        property list<string> reasons: []
        title: qsTr("The checklist does not pass")
        modal: true
        parent: Overlay.overlay
        anchors.centerIn: parent
        width: 460
        ColumnLayout {
            width: overrideDialog.availableWidth
            Label {
                textFormat: Text.PlainText
                Layout.fillWidth: true
                wrapMode: Text.Wrap
                text: qsTr("%1 is held back on %2 by:").arg(bar.policy.commandLabel(overrideDialog.command))
                                                         .arg(overrideDialog.vehicle ? overrideDialog.vehicle.name : "")
            }
            Label {
                textFormat: Text.PlainText
                objectName: "checklistOverrideReasons"
                Layout.fillWidth: true
                Layout.leftMargin: 12
                wrapMode: Text.Wrap
                color: bar.theme.problemText
                text: overrideDialog.reasons.map(r => "• " + r).join("\n")
            }
            Label {
                textFormat: Text.PlainText
                Layout.fillWidth: true
                wrapMode: Text.Wrap
                text: qsTr("Send it anyway? The override and these reasons go into the command log and the flight log.")
            }
        }
        footer: DialogButtonBox {
            Button {
                objectName: "checklistOverrideButton"
                text: qsTr("Send anyway")
                DialogButtonBox.buttonRole: DialogButtonBox.AcceptRole
            }
            Button {
                objectName: "checklistOverrideCancel"
                text: qsTr("Cancel")
                DialogButtonBox.buttonRole: DialogButtonBox.RejectRole
            }
        }
        onAccepted: if (overrideDialog.vehicle) bar.policy.sendOverriding(overrideDialog.command, overrideDialog.vehicle)
    }

    Popup {
        id: checklistPopup
        objectName: "checklistPopup"
        parent: Overlay.overlay
        x: Math.round((parent.width - width) / 2)
        y: Math.round((parent.height - height) / 2)
        width: Math.min(520, parent.width - 40)
        height: Math.min(checklistPanel.implicitHeight + topPadding + bottomPadding, parent.height - 40)
        modal: false
        closePolicy: Popup.CloseOnEscape | Popup.CloseOnPressOutside
        ChecklistPanel {
            id: checklistPanel
            anchors.fill: parent
            theme: bar.theme
            preflight: bar.preflight
            checklist: bar.checklist
        }
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
        Button {
            objectName: "checklistButton"
            visible: bar.checklist !== null
            text: !bar.checklist ? "" : bar.checklist.holdingCount === 0 ? qsTr("Checklist ✓")
                                                                       : qsTr("Checklist: %n to do", "", bar.checklist.holdingCount)
            checkable: true
            checked: checklistPopup.opened
            onClicked: checklistPopup.opened ? checklistPopup.close() : checklistPopup.open()
            ToolTip.visible: hovered
            ToolTip.text: qsTr("The pre-flight checklist: Arm and Auto wait for its required items")
        }
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
            objectName: "gamepadButton"
            visible: bar.gamepads !== null
            text: qsTr("Gamepad")
            checkable: true
            checked: bar.gamepads !== null && bar.gamepads.enabled
            onToggled: { bar.gamepads.enabled = checked; checked = Qt.binding(() => bar.gamepads !== null && bar.gamepads.enabled) }
            ToolTip.visible: hovered
            ToolTip.text: bar.gamepads ? qsTr("Gamepad buttons as commands, each asking first (by default Start arms, X pauses, Y lands, B returns home). %1").arg(bar.gamepads.status) : ""
        }
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
