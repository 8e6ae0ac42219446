import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// One vehicle's pre-flight checklist (core/preflight): what the program checked, with what it
// found, and the items the operator ticks. Which items hold back Arm and Auto is the checklist's
// rule; this only shows it (a red mark: it holds a command back; amber: advisory or not known).
ColumnLayout {
    id: panel
    objectName: "checklistPanel"
    required property Theme theme
    required property PreflightChecklists preflight
    required property VehicleChecklist checklist   // null: no vehicle chosen
    spacing: 4

    RowLayout {
        Layout.fillWidth: true
        Label {
            textFormat: Text.PlainText
            objectName: "checklistName"
            Layout.fillWidth: true
            elide: Text.ElideRight
            font.bold: true
            text: panel.checklist ? panel.checklist.name : qsTr("Pre-flight checklist")
        }
        Label {
            textFormat: Text.PlainText
            objectName: "checklistReadiness"
            visible: panel.checklist !== null
            text: !panel.checklist ? ""
                  : panel.checklist.readyToArm && panel.checklist.readyForAuto ? qsTr("Ready to arm and fly the mission")
                  : panel.checklist.readyToArm ? qsTr("Ready to arm; Auto waits")
                  : qsTr("Not ready to arm: %1 of %2 pass").arg(panel.checklist.passedCount).arg(panel.checklist.count)
            color: !panel.checklist || !panel.checklist.readyToArm ? panel.theme.problemText
                   : panel.checklist.readyForAuto ? panel.theme.okText : panel.theme.warningText
        }
    }
    Label {
        textFormat: Text.PlainText
        objectName: "checklistSource"
        Layout.fillWidth: true
        wrapMode: Text.Wrap
        font.pixelSize: 11
        visible: panel.checklist !== null
        text: !panel.checklist ? ""
              : panel.checklist.sourceError.length > 0 ? qsTr("Not used, Sortie's default instead: %1").arg(panel.checklist.sourceError)
              : panel.checklist.source.length > 0 ? panel.checklist.source
              : qsTr("Sortie's default; write your own in %1").arg(panel.preflight.folder)
        color: panel.checklist && panel.checklist.sourceError.length > 0 ? panel.theme.problemText : panel.theme.missingText
    }
    Label {
        textFormat: Text.PlainText
        visible: panel.checklist === null
        Layout.fillWidth: true
        wrapMode: Text.Wrap
        text: qsTr("Choose a vehicle to see its checklist.")
    }
    ListView {
        id: items
        objectName: "checklistItems"
        Layout.fillWidth: true
        Layout.fillHeight: true
        Layout.preferredHeight: contentHeight   // the popup fits the list; a long one scrolls
        clip: true
        model: panel.checklist
        ScrollBar.vertical: ScrollBar {}
        delegate: RowLayout {
            id: row
            required property int index
            required property string title
            required property string detail
            required property int outcome
            required property bool manual
            required property bool ticked
            required property bool required
            required property bool holdsBack
            objectName: "checklistItem" + index
            width: ListView.view.width
            spacing: 6
            readonly property bool passed: outcome === VehicleChecklist.Pass || outcome === VehicleChecklist.Ticked
            CheckBox {
                objectName: "checklistTick" + row.index
                visible: row.manual
                checked: row.ticked
                padding: 0
                onToggled: panel.checklist.setTicked(row.index, checked)
            }
            Label {
                textFormat: Text.PlainText
                visible: !row.manual
                Layout.preferredWidth: 18
                horizontalAlignment: Text.AlignHCenter
                font.bold: true
                text: row.passed ? "✓" : row.outcome === VehicleChecklist.NotReported ? "–"
                      : row.outcome === VehicleChecklist.Missing ? "?" : "✗"
                color: row.passed ? panel.theme.okText : row.holdsBack ? panel.theme.problemText : panel.theme.warningText
            }
            Label {
                textFormat: Text.PlainText
                Layout.fillWidth: true
                wrapMode: Text.Wrap
                text: row.required ? row.title : qsTr("%1 (advisory)").arg(row.title)
            }
            Label {
                textFormat: Text.PlainText
                objectName: "checklistDetail" + row.index
                Layout.maximumWidth: items.width * 0.45
                horizontalAlignment: Text.AlignRight
                wrapMode: Text.Wrap
                font.pixelSize: 11
                text: row.detail
                color: row.passed ? panel.theme.missingText : row.holdsBack ? panel.theme.problemText : panel.theme.warningText
            }
        }
    }
    RowLayout {
        Layout.fillWidth: true
        Button {
            objectName: "checklistReloadButton"
            text: qsTr("Read again")
            flat: true
            onClicked: panel.preflight.reload()
            ToolTip.visible: hovered
            ToolTip.text: qsTr("Read the checklist files again after editing them (the ticks are cleared)")
        }
        Item { Layout.fillWidth: true }
    }
}
