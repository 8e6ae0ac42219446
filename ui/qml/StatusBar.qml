import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The window's bottom line: connection state (always visible), what the map shows, and the
// coordinates under the cursor.
ToolBar {
    id: bar
    property string connectionState: "Disconnected"           // the key: it picks the colour
    property string connectionStateText: connectionState     // what the operator reads
    property string connectionDetail: ""
    required property MapView map
    required property DisplayUnits units
    required property Theme theme

    readonly property color stateColor: connectionState === "Ready" ? theme.ok
                                      : connectionState === "Disconnected" ? theme.missing
                                      : connectionState === "Reconnecting" ? theme.warning : theme.info
    RowLayout {
        anchors.fill: parent
        anchors.leftMargin: 8
        anchors.rightMargin: 8
        spacing: 12
        Rectangle {
            width: 10; height: 10; radius: 5
            color: bar.stateColor
        }
        Label {
            textFormat: Text.PlainText
            objectName: "connectionStateLabel"
            text: bar.connectionDetail.length > 0 ? bar.connectionStateText + " — " + bar.connectionDetail : bar.connectionStateText
            elide: Text.ElideRight
            Layout.maximumWidth: 420
        }
        ToolSeparator {}
        Label {
            textFormat: Text.PlainText
            objectName: "tileStatusLabel"
            text: bar.map.tileStatus
            elide: Text.ElideRight
            Layout.fillWidth: true
        }
        Label {
            textFormat: Text.PlainText
            objectName: "cursorLabel"
            text: bar.map.cursorInside ? bar.units.formatCoordinate(bar.map.cursorCoordinate) : ""
            font.family: "monospace"
        }
        Label {
            textFormat: Text.PlainText
            objectName: "zoomLabel"
            text: qsTr("zoom %1").arg(bar.map.zoomLevel.toFixed(1))
        }
    }
}
