import QtQuick
import QtQuick.Controls
import Sortie.Ui

// The question the route library asks before opening a route over unsaved edits: Save, Discard
// (Undo brings them back) or Cancel. The controller decides when to ask and what; this only shows
// it and answers.
Dialog {
    id: dialog
    objectName: "openQuestion"
    required property MissionController missions

    title: qsTr("Unsaved edits")
    modal: true
    parent: Overlay.overlay
    anchors.centerIn: parent
    width: Math.min(480, parent ? parent.width - 40 : 480)
    closePolicy: Popup.CloseOnEscape
    onRejected: if (missions.askingToOpen) missions.cancelOpen()

    Connections {
        target: dialog.missions
        function onOpenQuestionChanged() {
            if (dialog.missions.askingToOpen)
                dialog.open()
            else
                dialog.close()
        }
    }

    Label {
        objectName: "openQuestionText"
        width: dialog.availableWidth
        wrapMode: Text.Wrap
        textFormat: Text.PlainText
        text: dialog.missions.openQuestion
    }

    footer: DialogButtonBox {
        Button {
            objectName: "saveThenOpenButton"
            text: qsTr("Save")
            DialogButtonBox.buttonRole: DialogButtonBox.AcceptRole
        }
        Button {
            objectName: "discardThenOpenButton"
            text: qsTr("Discard")
            DialogButtonBox.buttonRole: DialogButtonBox.DestructiveRole
        }
        Button {
            objectName: "cancelOpenButton"
            text: qsTr("Cancel")
            DialogButtonBox.buttonRole: DialogButtonBox.RejectRole
        }
        onAccepted: dialog.missions.saveThenOpen()
        onClicked: button => { if (button.DialogButtonBox.buttonRole === DialogButtonBox.DestructiveRole) dialog.missions.discardThenOpen() }
    }
}
