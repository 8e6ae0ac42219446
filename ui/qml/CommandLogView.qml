import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// What was asked of the vehicles and what they answered, newest at the bottom: time, vehicle,
// command, result. The fleet's CommandLog holds it; this only lists it.
ColumnLayout {
    id: view
    required property Theme theme
    objectName: "commandLogView"
    required property CommandLog log
    spacing: 2

    Label { textFormat: Text.PlainText; text: qsTr("Command log"); font.bold: true }
    ListView {
        id: list
        objectName: "commandLogList"
        Layout.fillWidth: true
        Layout.fillHeight: true
        clip: true
        model: view.log
        ScrollBar.vertical: ScrollBar {}
        onCountChanged: positionViewAtEnd()
        delegate: Label {
            textFormat: Text.PlainText
            required property var model
            width: ListView.view.width
            wrapMode: Text.Wrap
            font.pixelSize: 12
            text: model.text
            color: model.failed ? view.theme.problemText : palette.windowText
        }
    }
}
