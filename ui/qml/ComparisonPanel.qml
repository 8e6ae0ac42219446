import QtQuick
import QtQuick.Controls
import QtQuick.Dialogs
import QtQuick.Layouts
import Sortie.Ui

// The replayed flight against its plan: choose a route file, then a line of totals and a table of
// legs (largest and mean cross-track and altitude deviation, when the leg's end was reached), each
// row coloured like the track on the map. The ComparisonController computes everything.
ColumnLayout {
    id: panel
    required property Theme theme
    required property ComparisonController comparison
    property int vehicleIndex: -1
    spacing: 2

    FileDialog {
        id: routeDialog
        title: qsTr("Compare with a route")
        nameFilters: [qsTr("Routes (*.sortie *.plan *.waypoints *.wpl *.txt)"), qsTr("All files (*)")]
        onAccepted: panel.comparison.compare(selectedFile.toString(), panel.vehicleIndex)
    }
    RowLayout {
        Button {
            objectName: "compareButton"
            text: qsTr("Compare with route…")
            onClicked: routeDialog.open()
        }
        Label {
            textFormat: Text.PlainText
            objectName: "comparisonSummary"
            Layout.fillWidth: true
            text: panel.comparison.errorString.length > 0 ? panel.comparison.errorString : panel.comparison.summary
            color: panel.comparison.errorString.length > 0 ? panel.theme.problemText : palette.windowText
            elide: Text.ElideRight
        }
        Button {
            visible: panel.comparison.available
            text: qsTr("Clear")
            onClicked: panel.comparison.clear()
        }
    }
    ListView {
        objectName: "comparisonTable"
        visible: panel.comparison.available
        Layout.fillWidth: true
        Layout.preferredHeight: Math.min(contentHeight, 140)
        clip: true
        model: panel.comparison.legs
        header: RowLayout {
            width: ListView.view.width
            Repeater {
                model: [qsTr("leg"), qsTr("samples"), qsTr("cross-track max"), qsTr("mean"), qsTr("altitude max"), qsTr("mean"), qsTr("reached")]
                Label { textFormat: Text.PlainText; required property string modelData; text: modelData; font.bold: true; Layout.fillWidth: true }
            }
        }
        delegate: RowLayout {
            required property string leg
            required property int samples
            required property string maxCrossTrack
            required property string meanCrossTrack
            required property string maxAltitude
            required property string meanAltitude
            required property string reached
            required property int level
            width: ListView.view.width
            Rectangle { width: 8; height: 8; radius: 4; color: [panel.theme.ok, panel.theme.warning, panel.theme.problem][level] }
            Label { textFormat: Text.PlainText; text: leg; Layout.fillWidth: true }
            Label { textFormat: Text.PlainText; text: samples; Layout.fillWidth: true }
            Label { textFormat: Text.PlainText; text: qsTr("%1 m").arg(maxCrossTrack); Layout.fillWidth: true }
            Label { textFormat: Text.PlainText; text: qsTr("%1 m").arg(meanCrossTrack); Layout.fillWidth: true }
            Label { textFormat: Text.PlainText; text: qsTr("%1 m").arg(maxAltitude); Layout.fillWidth: true }
            Label { textFormat: Text.PlainText; text: qsTr("%1 m").arg(meanAltitude); Layout.fillWidth: true }
            Label { textFormat: Text.PlainText; text: reached; Layout.fillWidth: true }
        }
    }
}
