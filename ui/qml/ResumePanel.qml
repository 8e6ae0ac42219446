import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The fly view's offer to finish a mission the chosen vehicle stopped half-way (MissionResume):
// once it stands disarmed, from the last photo it took on that route or the last waypoint it
// reached. The rest opens in the mission editor, chosen for the vehicle, where every rule checks it
// before it goes up.
Rectangle {
    id: panel
    required property Theme theme
    required property MissionResume resume   // null without vehicles
    readonly property bool offered: panel.resume !== null && panel.resume.available
    visible: panel.offered || (panel.resume !== null && panel.resume.errorString !== "")
    implicitHeight: column.implicitHeight + 8
    color: panel.theme.alternateBase
    border.color: panel.theme.mid

    ColumnLayout {
        id: column
        anchors.fill: parent
        anchors.margins: 4
        anchors.leftMargin: 6
        anchors.rightMargin: 6
        spacing: 2
        RowLayout {
            Layout.fillWidth: true
            spacing: 8
            Label {
                textFormat: Text.PlainText
                objectName: "resumeSummary"
                Layout.fillWidth: true
                text: panel.offered ? panel.resume.summary : ""
                wrapMode: Text.Wrap
            }
            Button {
                objectName: "resumeFromPhotoButton"
                visible: panel.offered
                enabled: panel.resume !== null && panel.resume.fromPhotoAvailable
                text: qsTr("Resume from the last photo")
                onClicked: panel.resume.resumeFromLastPhoto()
            }
            Button {
                objectName: "resumeFromWaypointButton"
                visible: panel.offered
                enabled: panel.resume !== null && panel.resume.fromWaypointAvailable
                text: qsTr("Resume from the last waypoint")
                onClicked: panel.resume.resumeFromLastWaypoint()
            }
        }
        Label {
            textFormat: Text.PlainText
            objectName: "resumeError"
            Layout.fillWidth: true
            visible: text !== ""
            text: panel.resume !== null ? panel.resume.errorString : ""
            color: panel.theme.problemText
            wrapMode: Text.Wrap
        }
    }
}
