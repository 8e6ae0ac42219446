import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The chosen vehicle's live video (docs/video.md): the picture with what the receiver says over it,
// and under it the vehicle's URL (empty: the one the vehicle publishes, video_stream_uri; typed: the
// operator's, kept per vehicle) and Swap, which trades places with the map (picture in picture).
Rectangle {
    id: panel
    required property Theme theme
    required property VehicleVideo video   // null in a graph without vehicles
    property Vehicle vehicle: null
    property bool swapped: false
    readonly property VideoReceiver receiver: video && vehicle ? video.receiverFor(vehicle) : null
    readonly property alias picture: picture
    property Vehicle shown: null
    objectName: "videoPanel"
    color: theme.window
    border.color: theme.mid
    radius: 3
    implicitWidth: 360
    implicitHeight: 360 * 9 / 16 + bar.implicitHeight + 8

    // A receiver for the vehicle shown, none kept for the one before.
    onVehicleChanged: {
        if (shown && shown !== vehicle && video)
            video.release(shown)
        shown = vehicle
    }

    ColumnLayout {
        anchors.fill: parent
        anchors.margins: 3
        spacing: 3
        VideoItem {
            id: picture
            objectName: "videoItem"
            Layout.fillWidth: true
            Layout.fillHeight: true
            receiver: panel.receiver
            compact: !panel.swapped
        }
        RowLayout {
            id: bar
            Layout.fillWidth: true
            spacing: 3
            TextField {
                id: urlField
                objectName: "videoUrlField"
                Layout.fillWidth: true
                enabled: panel.vehicle !== null && panel.video !== null
                placeholderText: panel.vehicle && panel.vehicle.videoStreamUri !== "" ? panel.vehicle.videoStreamUri
                                                                                       : qsTr("rtsp://, udp://:5600 or an .sdp file")
                text: panel.vehicle && panel.video ? panel.video.manualUrl(panel.vehicle) : ""
                selectByMouse: true
                onAccepted: panel.video.setManualUrl(panel.vehicle, text)
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: qsTr("This vehicle's video: empty plays the stream the vehicle publishes; a URL typed here overrides it and is remembered.")
            }
            Button {
                objectName: "videoRecordButton"
                text: qsTr("Record")
                checkable: true
                visible: panel.video !== null && panel.video.canRecord
                enabled: panel.receiver !== null
                checked: panel.receiver !== null && panel.receiver.recording
                onToggled: panel.video.setRecording(panel.vehicle, checked)
                ToolTip.visible: hovered
                ToolTip.delay: 600
                ToolTip.text: panel.receiver && panel.receiver.recording ? qsTr("Recording to %1").arg(panel.receiver.recordingFile)
                                                                         : qsTr("Record this video as received, beside the flight log")
            }
            Button {
                objectName: "videoSwapButton"
                text: panel.swapped ? qsTr("Map") : qsTr("Swap")
                onClicked: panel.swapped = !panel.swapped
            }
        }
    }
}
