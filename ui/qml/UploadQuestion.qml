import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The one question the uploader asks before a route goes to a vehicle: its warnings and unsaved
// edits, listed. The uploader decides when to ask and what; this only shows it and answers.
Dialog {
    id: dialog
    objectName: "uploadQuestion"
    required property MissionUploader uploader
    signal saveAndUpload()

    title: qsTr("Upload the route?")
    modal: true
    parent: Overlay.overlay
    anchors.centerIn: parent
    width: Math.min(560, parent ? parent.width - 40 : 560)
    closePolicy: Popup.CloseOnEscape
    onRejected: if (uploader.asking) uploader.cancel()

    Connections {
        target: dialog.uploader
        function onStateChanged() {
            if (dialog.uploader.asking)
                dialog.open()
            else
                dialog.close()
        }
    }

    ScrollView {
        anchors.fill: parent
        implicitHeight: Math.min(question.implicitHeight, 320)
        Label {
            textFormat: Text.PlainText
            id: question
            objectName: "uploadQuestionText"
            width: dialog.availableWidth
            wrapMode: Text.Wrap
            text: dialog.uploader.question
        }
    }

    footer: DialogButtonBox {
        Button {
            objectName: "uploadAnywayButton"
            text: dialog.uploader && dialog.uploader.unsavedEdits ? qsTr("Upload without saving") : qsTr("Upload")
            DialogButtonBox.buttonRole: DialogButtonBox.AcceptRole
        }
        Button {
            objectName: "saveAndUploadButton"
            text: qsTr("Save and upload")
            visible: dialog.uploader.unsavedEdits
            DialogButtonBox.buttonRole: DialogButtonBox.ApplyRole
        }
        Button {
            text: qsTr("Cancel")
            DialogButtonBox.buttonRole: DialogButtonBox.RejectRole
        }
        onAccepted: dialog.uploader.confirm()
        onApplied: dialog.saveAndUpload()
    }
}
