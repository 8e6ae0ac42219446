import QtQuick
import QtQuick.Controls
import QtQuick.Dialogs
import QtQuick.Layouts
import Sortie.Ui

// After landing (issue 34): the replayed flight's photos placed on its log and the ground they
// cover, then their geotagged copies written. The folder, the camera and the camera clock's offset
// are the operator's; PhotoSurvey places, judges and writes on a worker thread; this is a view.
Dialog {
    id: dialog
    property Theme theme: Theme {}
    required property DisplayUnits units
    required property PhotoSurvey survey
    property int vehicleIndex: -1   // the log's vehicle the fly view has chosen

    objectName: "photosDialog"
    title: qsTr("Photos of the flight")
    modal: true
    parent: Overlay.overlay
    anchors.centerIn: parent
    width: Math.min(parent ? parent.width - 80 : 640, 640)
    height: Math.min(parent ? parent.height - 80 : 620, 620)
    standardButtons: Dialog.Close

    FolderDialog {
        id: photoFolderDialog
        objectName: "photoFolderPicker"
        parentWindow: photoFolderField.Window.window  // the dialog's window, once it has one
        title: qsTr("The folder of the flight's photos")
        onAccepted: dialog.survey.photoFolder = selectedFolder.toString()
    }
    FolderDialog {
        id: outFolderDialog
        objectName: "copiesFolderPicker"
        parentWindow: photoFolderField.Window.window
        title: qsTr("Where the geotagged copies go")
        onAccepted: dialog.survey.writeCopies(selectedFolder.toString())
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 8
        GridLayout {
            columns: 3
            columnSpacing: 8
            rowSpacing: 6
            Layout.fillWidth: true
            Label { textFormat: Text.PlainText; text: qsTr("Photos") }
            TextField {
                id: photoFolderField
                objectName: "photoFolderField"
                Layout.fillWidth: true
                selectByMouse: true
                placeholderText: qsTr("a folder of JPEG, TIFF or DNG photos")
                text: dialog.survey.photoFolder
                onEditingFinished: dialog.survey.photoFolder = text
            }
            Button {
                objectName: "photoFolderButton"
                text: qsTr("Choose…")
                onClicked: photoFolderDialog.open()
            }
            Label { textFormat: Text.PlainText; text: qsTr("Camera") }
            ComboBox {
                objectName: "photoCameraBox"
                Layout.fillWidth: true
                Layout.columnSpan: 2
                model: dialog.survey.cameras
                currentIndex: Math.max(0, dialog.survey.cameras.indexOf(dialog.survey.camera))
                onActivated: index => dialog.survey.camera = dialog.survey.cameras[index]
            }
            Label { textFormat: Text.PlainText; text: qsTr("Camera clock behind the log (s)") }
            NumberField {
                objectName: "photoOffsetField"
                theme: dialog.theme
                units: dialog.units
                value: dialog.survey.offsetSeconds
                decimals: 1
                from: -86400
                to: 86400
                hint: qsTr("Seconds added to each photo's time: how far the camera's clock is behind the log's (GNSS) time")
                onNumberEntered: number => dialog.survey.offsetSeconds = number
            }
            Button {
                objectName: "placePhotosButton"
                text: qsTr("Place photos")
                enabled: !dialog.survey.busy && dialog.vehicleIndex >= 0
                onClicked: dialog.survey.match(dialog.vehicleIndex)
            }
        }
        BusyIndicator {
            objectName: "photosBusy"
            visible: dialog.survey.busy
            running: visible
            Layout.alignment: Qt.AlignHCenter
        }
        Label {
            textFormat: Text.PlainText
            objectName: "photosError"
            visible: text.length > 0
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            color: dialog.theme.problemText
            text: dialog.survey.errorString
        }
        Label {
            textFormat: Text.PlainText
            objectName: "photosSummary"
            visible: text.length > 0
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            font.bold: true
            text: dialog.survey.summary
        }
        Label {
            textFormat: Text.PlainText
            objectName: "coverageSummary"
            visible: text.length > 0
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            color: dialog.survey.holeCount > 0 ? dialog.theme.problemText : dialog.theme.okText
            text: dialog.survey.coverageSummary
        }
        RowLayout {
            Layout.fillWidth: true
            visible: dialog.survey.holeCount > 0
            Label {
                textFormat: Text.PlainText
                Layout.fillWidth: true
                text: qsTr("Holes, largest first (shaded on the map):")
            }
            Button {
                objectName: "reflyButton"
                text: qsTr("Re-fly the gaps")
                enabled: dialog.survey.canRefly && !dialog.survey.busy
                ToolTip.visible: hovered
                ToolTip.text: qsTr("A route of an area scan per hole, with the survey's camera, height and overlap, opened in the mission editor")
                onClicked: dialog.survey.reflyGaps()
            }
        }
        Label {
            textFormat: Text.PlainText
            objectName: "reflyText"
            visible: text.length > 0
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            text: dialog.survey.reflyText
        }
        ListView {
            objectName: "holeList"
            visible: dialog.survey.holeCount > 0
            Layout.fillWidth: true
            Layout.preferredHeight: Math.min(contentHeight, 90)
            clip: true
            model: dialog.survey.holeList
            delegate: Label { textFormat: Text.PlainText; required property string modelData; text: modelData; width: ListView.view.width; elide: Text.ElideRight }
        }
        Label {
            textFormat: Text.PlainText
            visible: dialog.survey.unplaced.length > 0
            text: qsTr("Not placed:")
        }
        ListView {
            objectName: "unplacedList"
            visible: dialog.survey.unplaced.length > 0
            Layout.fillWidth: true
            Layout.fillHeight: true
            Layout.minimumHeight: 40
            clip: true
            model: dialog.survey.unplaced
            delegate: Label { textFormat: Text.PlainText; required property string modelData; text: modelData; width: ListView.view.width; wrapMode: Text.Wrap }
            ScrollBar.vertical: ScrollBar {}
        }
        Item { Layout.fillHeight: true; visible: dialog.survey.unplaced.length === 0 }
        RowLayout {
            Layout.fillWidth: true
            Label {
                textFormat: Text.PlainText
                objectName: "photosWritten"
                Layout.fillWidth: true
                wrapMode: Text.Wrap
                text: dialog.survey.written
            }
            Button {
                objectName: "writeCopiesButton"
                text: qsTr("Write geotagged copies…")
                enabled: !dialog.survey.busy && dialog.survey.placedCount > 0
                onClicked: outFolderDialog.open()
            }
        }
    }
}
