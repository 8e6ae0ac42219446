import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Offered at start when a previous run left unsaved edits behind (it crashed, or quit without
// saving): what they change since the last save, and Restore or Discard. `recovery` is the
// client's AutosaveRecovery; the decisions are its.
Dialog {
    id: dialog
    required property AutosaveRecovery recovery
    signal restored()
    title: qsTr("Restore unsaved edits?")
    modal: true
    closePolicy: Popup.NoAutoClose
    anchors.centerIn: parent
    width: Math.min(parent ? parent.width - 80 : 560, 560)

    ColumnLayout {
        anchors.fill: parent
        spacing: 8
        Label {
            objectName: "restoreIntro"
            text: dialog.recovery ? qsTr("Sortie did not close normally. Edits of “%1” were saved automatically at %2.")
                                        .arg(dialog.recovery.routeName)
                                        .arg(Qt.formatDateTime(dialog.recovery.savedAt, Qt.DefaultLocaleShortDate)) : ""
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
        Label {
            visible: text.length > 0
            text: dialog.recovery && dialog.recovery.origin.length > 0 ? qsTr("It belongs to %1.").arg(dialog.recovery.origin) : ""
            wrapMode: Text.Wrap
            opacity: 0.7
            Layout.fillWidth: true
        }
        Label { text: qsTr("Changes since the last save:"); font.bold: true }
        ListView {
            objectName: "restoreChanges"
            Layout.fillWidth: true
            Layout.preferredHeight: Math.min(contentHeight, 220)
            clip: true
            model: dialog.recovery ? dialog.recovery.changes : []
            delegate: Label { required property string modelData; text: "• " + modelData; wrapMode: Text.Wrap; width: ListView.view.width }
        }
        RowLayout {
            Layout.alignment: Qt.AlignRight
            Button {
                objectName: "discardAutosaveButton"
                text: qsTr("Discard")
                onClicked: dialog.recovery.discard()
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Start without them (the file is kept as a backup)")
            }
            Button {
                objectName: "restoreAutosaveButton"
                text: qsTr("Restore")
                highlighted: true
                onClicked: if (dialog.recovery.restore()) dialog.restored()
            }
        }
    }
}
