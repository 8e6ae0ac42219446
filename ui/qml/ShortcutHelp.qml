import QtQuick
import QtQuick.Controls
import QtQuick.Layouts

// The keyboard help overlay (F1): every shortcut and map key with what it does, the window's
// shortcuts beside the map's keys so that the whole list fits a laptop screen.
Popup {
    id: help
    required property Shortcuts shortcuts
    modal: true
    focus: true
    anchors.centerIn: Overlay.overlay
    width: Math.min(parent ? parent.width - 80 : 980, 980)
    padding: 20
    closePolicy: Popup.CloseOnEscape | Popup.CloseOnPressOutside

    // One column of keys and what they do; the descriptions wrap within the column.
    component KeyList: GridLayout {
        id: list
        property var entries: []
        property var keysOf
        columns: 2
        columnSpacing: 16
        rowSpacing: 6
        Repeater {
            model: list.entries
            delegate: Label {
                textFormat: Text.PlainText
                required property var modelData
                required property int index
                Layout.row: index
                Layout.column: 0
                Layout.alignment: Qt.AlignTop
                font.family: "monospace"
                text: list.keysOf(modelData)
            }
        }
        Repeater {
            model: list.entries
            delegate: Label {
                textFormat: Text.PlainText
                required property var modelData
                required property int index
                Layout.row: index
                Layout.column: 1
                Layout.fillWidth: true
                Layout.alignment: Qt.AlignTop
                wrapMode: Text.Wrap
                text: modelData.help
            }
        }
    }

    contentItem: ColumnLayout {
        spacing: 12
        Label {
            textFormat: Text.PlainText
            text: qsTr("Keyboard shortcuts")
            font.bold: true
            font.pixelSize: 18
        }
        RowLayout {
            Layout.fillWidth: true
            spacing: 32
            KeyList {
                objectName: "shortcutGrid"
                Layout.fillWidth: true
                Layout.preferredWidth: 1
                Layout.alignment: Qt.AlignTop
                entries: help.shortcuts ? help.shortcuts.entries : []
                keysOf: entry => entry.nativeText.length > 0 ? entry.nativeText : entry.sequences.join(", ")
            }
            ColumnLayout {
                Layout.fillWidth: true
                Layout.preferredWidth: 1
                Layout.alignment: Qt.AlignTop
                spacing: 8
                Label {
                    textFormat: Text.PlainText
                    text: qsTr("On the map")
                    font.bold: true
                }
                KeyList {
                    objectName: "mapKeyGrid"
                    Layout.fillWidth: true
                    entries: help.shortcuts ? help.shortcuts.mapKeys : []
                    keysOf: entry => entry.keys
                }
            }
        }
        Label {
            textFormat: Text.PlainText
            text: qsTr("Esc closes this help.")
            opacity: 0.7
        }
    }
}
