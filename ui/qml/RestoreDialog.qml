import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Offered at start when previous runs left unsaved edits behind (they crashed, or quit without
// saving): every such autosave in one list, newest first; for the chosen one, what it changes
// since the last save, and Restore, Discard or Later. `recovery` is the client's
// AutosaveRecovery; the decisions are its, including why a restore is not possible now
// (`restoreBlocker`: another server or user, or unsaved edits open). What went wrong with an
// autosave (`message`: an unreadable file kept aside) is shown too, alone when nothing is offered.
Dialog {
    id: dialog
    required property Theme theme
    required property AutosaveRecovery recovery
    signal restored()
    readonly property int count: recovery ? recovery.count : 0
    readonly property bool offering: recovery !== null && recovery.available
    title: !offering ? qsTr("Autosaved edits")
           : count > 1 ? qsTr("Restore one of %1 unsaved routes?").arg(count) : qsTr("Restore unsaved edits?")
    modal: true
    closePolicy: Popup.NoAutoClose
    anchors.centerIn: parent
    width: Math.min(parent ? parent.width - 80 : 620, 620)

    ColumnLayout {
        anchors.fill: parent
        spacing: 8
        Label {
            textFormat: Text.PlainText
            objectName: "restoreIntro"
            visible: dialog.offering
            text: !dialog.recovery ? ""
                  : dialog.count > 1 ? qsTr("Sortie did not close normally. These routes had unsaved edits, saved automatically. Choose one to see its changes; the others are kept and offered again at the next start.")
                  : qsTr("Sortie did not close normally. Edits of “%1” were saved automatically at %2.")
                        .arg(dialog.recovery.routeName)
                        .arg(Qt.formatDateTime(dialog.recovery.savedAt, Qt.DefaultLocaleShortDate))
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
        ListView {
            id: autosaves
            objectName: "autosaveList"
            visible: dialog.offering && dialog.count > 1
            Layout.fillWidth: true
            Layout.preferredHeight: Math.min(contentHeight, 180)
            clip: true
            model: dialog.recovery
            currentIndex: dialog.recovery ? dialog.recovery.currentRow : -1
            ScrollBar.vertical: ScrollBar {}
            delegate: ItemDelegate {
                required property int index
                required property string routeName
                required property date savedAt
                required property string origin
                required property string summary
                required property string restoreBlocker
                width: ListView.view.width
                highlighted: ListView.isCurrentItem
                onClicked: dialog.recovery.currentRow = index
                contentItem: ColumnLayout {
                    spacing: 2
                    Label {
                        textFormat: Text.PlainText
                        text: qsTr("%1 — saved %2").arg(routeName).arg(Qt.formatDateTime(savedAt, Qt.DefaultLocaleShortDate))
                        font.bold: true
                        elide: Text.ElideRight
                        Layout.fillWidth: true
                    }
                    Label {
                        textFormat: Text.PlainText
                        text: (origin.length > 0 ? origin + " · " : "") + summary
                        elide: Text.ElideRight
                        opacity: restoreBlocker.length > 0 ? 0.55 : 0.8
                        Layout.fillWidth: true
                    }
                }
            }
        }
        Label {
            textFormat: Text.PlainText
            visible: text.length > 0
            text: dialog.recovery && dialog.recovery.origin.length > 0 ? qsTr("It belongs to %1.").arg(dialog.recovery.origin) : ""
            wrapMode: Text.Wrap
            opacity: 0.7
            Layout.fillWidth: true
        }
        Label { textFormat: Text.PlainText; visible: dialog.offering; text: qsTr("Changes since the last save:"); font.bold: true }
        ListView {
            objectName: "restoreChanges"
            visible: dialog.offering
            Layout.fillWidth: true
            Layout.preferredHeight: Math.min(contentHeight, 180)
            clip: true
            model: dialog.recovery ? dialog.recovery.changes : []
            delegate: Label { textFormat: Text.PlainText; required property string modelData; text: "• " + modelData; wrapMode: Text.Wrap; width: ListView.view.width }
        }
        Label {
            textFormat: Text.PlainText
            objectName: "restoreBlocker"
            visible: text.length > 0
            text: dialog.recovery ? dialog.recovery.restoreBlocker : ""
            color: dialog.theme.problemText
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
        Label {
            textFormat: Text.PlainText
            objectName: "recoveryMessage"
            visible: text.length > 0
            text: dialog.recovery ? dialog.recovery.message : ""
            color: dialog.theme.problemText
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
        Button {
            objectName: "acknowledgeRecoveryButton"
            visible: !dialog.offering
            text: qsTr("OK")
            Layout.alignment: Qt.AlignRight
            onClicked: dialog.recovery.acknowledgeMessage()
        }
        RowLayout {
            visible: dialog.offering
            Layout.alignment: Qt.AlignRight
            Button {
                objectName: "discardAutosaveButton"
                text: qsTr("Discard")
                onClicked: dialog.recovery.discard()
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Start without these edits (the file is kept as a backup)")
            }
            Button {
                objectName: "laterAutosaveButton"
                text: qsTr("Later")
                onClicked: dialog.recovery.postpone()
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Keep them and decide after signing in")
            }
            Button {
                objectName: "restoreAutosaveButton"
                text: qsTr("Restore")
                highlighted: true
                enabled: dialog.recovery !== null && dialog.recovery.restoreBlocker.length === 0
                onClicked: if (dialog.recovery.restore()) dialog.restored()
            }
        }
    }
}
