import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Replay the connected server's telemetry history: choose one of its vehicles and a time range
// (UTC), fetch it page by page with progress (cancel stops it), and the replay opens it. The
// ServerHistoryRequest decides what is valid and does the work; this is a view of it.
Dialog {
    id: dialog
    required property Theme theme
    required property ServerHistoryRequest request

    objectName: "serverHistoryDialog"
    title: qsTr("Server history")
    modal: true
    parent: Overlay.overlay
    anchors.centerIn: parent
    width: Math.min(480, parent ? parent.width - 40 : 480)
    closePolicy: Popup.CloseOnEscape
    onOpened: request.reset()
    onClosed: request.cancel()

    Connections {
        target: dialog.request
        function onOpened() { dialog.close() }
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 8
        GridLayout {
            columns: 2
            columnSpacing: 8
            rowSpacing: 6
            Layout.fillWidth: true
            Label { textFormat: Text.PlainText; text: qsTr("Vehicle") }
            ComboBox {
                objectName: "historyVehicleBox"
                Layout.fillWidth: true
                enabled: !dialog.request.busy
                model: dialog.request.vehicles
                currentIndex: dialog.request.vehicleIndex
                onActivated: index => dialog.request.vehicleIndex = index
            }
            Label { textFormat: Text.PlainText; text: qsTr("From (UTC)") }
            TextField {
                objectName: "historyFromField"
                Layout.fillWidth: true
                enabled: !dialog.request.busy
                text: dialog.request.fromText
                onTextEdited: dialog.request.fromText = text
            }
            Label { textFormat: Text.PlainText; text: qsTr("To (UTC)") }
            RowLayout {
                Layout.fillWidth: true
                TextField {
                    objectName: "historyToField"
                    Layout.fillWidth: true
                    enabled: !dialog.request.busy
                    text: dialog.request.toText
                    onTextEdited: dialog.request.toText = text
                }
                Button {
                    objectName: "historyLastHourButton"
                    enabled: !dialog.request.busy
                    text: qsTr("Last hour")
                    onClicked: dialog.request.chooseLastHour()
                }
            }
        }
        Label {
            textFormat: Text.PlainText
            objectName: "historyProblem"
            visible: text.length > 0
            text: dialog.request.problem
            color: dialog.theme.warningText
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
        ProgressBar {
            objectName: "historyProgress"
            visible: dialog.request.busy
            value: dialog.request.progress
            Layout.fillWidth: true
        }
        Label {
            textFormat: Text.PlainText
            objectName: "historyError"
            visible: text.length > 0
            text: dialog.request.errorString
            color: dialog.theme.problemText
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
        RowLayout {
            Layout.fillWidth: true
            Item { Layout.fillWidth: true }
            Button {
                objectName: "historyFetchButton"
                text: qsTr("Fetch and replay")
                enabled: dialog.request.canFetch && !dialog.request.busy
                onClicked: dialog.request.fetch()
            }
            Button {
                objectName: "historyCancelButton"
                text: dialog.request.busy ? qsTr("Cancel") : qsTr("Close")
                onClicked: dialog.request.busy ? dialog.request.cancel() : dialog.close()
            }
        }
    }
}
