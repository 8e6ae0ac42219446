import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Where flight logs are recorded and how much they may take: the folder, what it holds now, the log
// being written, a log's size cap (a bigger log continues in a new part) and the folder's limit (the
// oldest logs are deleted beyond it). RecordingSettings checks, saves and applies; this is a view.
Dialog {
    id: dialog
    // Its colours; the window hands its own (a dialog shown alone follows the system's).
    property Theme theme: Theme {}
    required property RecordingSettings settings

    objectName: "flightLogSettingsDialog"
    title: qsTr("Flight logs")
    modal: true
    parent: Overlay.overlay
    anchors.centerIn: parent
    width: Math.min(parent ? parent.width - 80 : 560, 560)
    standardButtons: Dialog.Close

    onAboutToShow: {
        settings.refresh()
        fileBox.value = settings.maxFileMB
        folderBox.value = settings.maxFolderMB
    }

    Timer { // the folder grows while recording
        interval: 2000
        repeat: true
        running: dialog.visible
        onTriggered: dialog.settings.refresh()
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 8
        GridLayout {
            columns: 2
            columnSpacing: 12
            rowSpacing: 6
            Layout.fillWidth: true
            Label { textFormat: Text.PlainText; text: qsTr("Folder") }
            TextField {
                objectName: "logFolderField"
                Layout.fillWidth: true
                readOnly: true
                selectByMouse: true
                text: dialog.settings.folder
            }
            Label { textFormat: Text.PlainText; text: qsTr("Holds") }
            Label {
                textFormat: Text.PlainText
                objectName: "logFolderSize"
                Layout.fillWidth: true
                text: dialog.settings.folderSummary
            }
            Label { textFormat: Text.PlainText; text: qsTr("Recording to") }
            Label {
                textFormat: Text.PlainText
                objectName: "currentLogLabel"
                Layout.fillWidth: true
                elide: Text.ElideMiddle
                text: dialog.settings.currentLog.length > 0 ? dialog.settings.currentLog : qsTr("not recording")
            }
            Label { textFormat: Text.PlainText; text: qsTr("A log up to (MB)") }
            SpinBox {
                id: fileBox
                objectName: "maxFileBox"
                from: 0
                to: dialog.settings.largestMB
                editable: true
                stepSize: 16
            }
            Label { textFormat: Text.PlainText; text: qsTr("The folder up to (MB)") }
            SpinBox {
                id: folderBox
                objectName: "maxFolderBox"
                from: 0
                to: dialog.settings.largestMB
                editable: true
                stepSize: 256
            }
        }
        Label {
            textFormat: Text.PlainText
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            opacity: 0.7
            text: qsTr("0: no limit. A log over its size continues in a new part; beyond the folder's size the oldest logs are deleted, never the one being written.")
        }
        Label {
            textFormat: Text.PlainText
            objectName: "logSettingsError"
            visible: text.length > 0
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            color: dialog.theme.problemText
            text: dialog.settings.errorString
        }
        RowLayout {
            Layout.fillWidth: true
            Label {
                textFormat: Text.PlainText
                objectName: "logSettingsInForce"
                Layout.fillWidth: true
                elide: Text.ElideRight
                text: dialog.settings.limitsText
            }
            Button {
                objectName: "applyLogSettingsButton"
                text: qsTr("Apply")
                onClicked: dialog.settings.apply(fileBox.value, folderBox.value)
            }
        }
    }
}
