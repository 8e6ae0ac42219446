import QtQuick
import QtQuick.Controls
import QtQuick.Layouts

// The keyboard help overlay (F1): every shortcut and map key with what it does.
Popup {
    id: help
    required property Shortcuts shortcuts
    modal: true
    focus: true
    anchors.centerIn: Overlay.overlay
    width: Math.min(parent ? parent.width - 80 : 640, 640)
    padding: 16
    closePolicy: Popup.CloseOnEscape | Popup.CloseOnPressOutside

    contentItem: ColumnLayout {
        spacing: 10
        Label {
            text: qsTr("Keyboard shortcuts")
            font.bold: true
            font.pixelSize: 18
        }
        GridLayout {
            objectName: "shortcutGrid"
            Layout.fillWidth: true
            columns: 2
            columnSpacing: 24
            rowSpacing: 6
            Repeater {
                model: help.shortcuts ? help.shortcuts.entries : []
                delegate: Label {
                    required property var modelData
                    required property int index
                    Layout.row: index
                    Layout.column: 0
                    font.family: "monospace"
                    Layout.alignment: Qt.AlignTop
                    text: modelData.nativeText.length > 0 ? modelData.nativeText : modelData.sequences.join(", ")
                }
            }
            Repeater {
                model: help.shortcuts ? help.shortcuts.entries : []
                delegate: Label {
                    required property var modelData
                    required property int index
                    Layout.row: index
                    Layout.column: 1
                    Layout.fillWidth: true
                    wrapMode: Text.Wrap
                    text: modelData.help
                }
            }
        }
        Label {
            text: qsTr("On the map")
            font.bold: true
        }
        GridLayout {
            objectName: "mapKeyGrid"
            Layout.fillWidth: true
            columns: 2
            columnSpacing: 24
            rowSpacing: 6
            Repeater {
                model: help.shortcuts ? help.shortcuts.mapKeys : []
                delegate: Label {
                    required property var modelData
                    required property int index
                    Layout.row: index
                    Layout.column: 0
                    font.family: "monospace"
                    Layout.alignment: Qt.AlignTop
                    text: modelData.keys
                }
            }
            Repeater {
                model: help.shortcuts ? help.shortcuts.mapKeys : []
                delegate: Label {
                    required property var modelData
                    required property int index
                    Layout.row: index
                    Layout.column: 1
                    Layout.fillWidth: true
                    wrapMode: Text.Wrap
                    text: modelData.help
                }
            }
        }
        Label {
            text: qsTr("Esc closes this help.")
            opacity: 0.7
        }
    }
}
