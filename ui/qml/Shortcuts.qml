import QtQuick

// Every window-wide keyboard shortcut, with the words the help overlay shows for it. Each one
// says what the operator asked for; the window decides what that does. Keys the focused map
// handles itself are listed in `mapKeys`.
QtObject {
    id: root
    signal helpRequested()
    signal pageRequested(int page)
    signal saveRequested()
    signal undoRequested()
    signal redoRequested()
    signal deleteRequested()
    signal processRequested()
    signal mapSourceRequested()
    signal mapFocusRequested()
    signal fullScreenRequested()

    readonly property var mapKeys: [
        { keys: "← ↑ → ↓", help: qsTr("Pan the map (Shift: faster)") },
        { keys: "+ / −", help: qsTr("Zoom in / out (also the mouse wheel and pinch)") },
        { keys: qsTr("Drag"), help: qsTr("Pan the map") },
        { keys: qsTr("Shift+Drag"), help: qsTr("Select waypoints in a rectangle (Ctrl+Shift adds)") },
        { keys: qsTr("Click"), help: qsTr("Add a waypoint; on a leg: insert one; on a waypoint: select (Ctrl toggles, Shift extends)") },
        { keys: qsTr("Drag a waypoint"), help: qsTr("Move it, or the whole selection") }
    ]

    property list<Shortcut> entries: [
        Shortcut {
            property string help: qsTr("Show or hide this help")
            sequences: ["F1", "?"]
            onActivated: root.helpRequested()
        },
        Shortcut {
            property string help: qsTr("Login page")
            sequence: "Ctrl+1"
            onActivated: root.pageRequested(0)
        },
        Shortcut {
            property string help: qsTr("Mission page")
            sequence: "Ctrl+2"
            onActivated: root.pageRequested(1)
        },
        Shortcut {
            property string help: qsTr("Live telemetry page")
            sequence: "Ctrl+3"
            onActivated: root.pageRequested(2)
        },
        Shortcut {
            property string help: qsTr("Save the route on the server")
            sequence: "Ctrl+S"
            onActivated: root.saveRequested()
        },
        Shortcut {
            property string help: qsTr("Undo")
            sequence: "Ctrl+Z"
            onActivated: root.undoRequested()
        },
        Shortcut {
            property string help: qsTr("Redo")
            sequences: ["Ctrl+Shift+Z", "Ctrl+Y"]
            onActivated: root.redoRequested()
        },
        Shortcut {
            property string help: qsTr("Delete the selected waypoints")
            sequence: "Del"
            onActivated: root.deleteRequested()
        },
        Shortcut {
            property string help: qsTr("Process the route on the server")
            sequence: "Ctrl+P"
            onActivated: root.processRequested()
        },
        Shortcut {
            property string help: qsTr("Choose the map source")
            sequence: "Ctrl+M"
            onActivated: root.mapSourceRequested()
        },
        Shortcut {
            property string help: qsTr("Focus the map (then arrows and +/− move it)")
            sequence: "Ctrl+L"
            onActivated: root.mapFocusRequested()
        },
        Shortcut {
            property string help: qsTr("Full screen on or off")
            sequence: "F11"
            onActivated: root.fullScreenRequested()
        },
        Shortcut {
            property string help: qsTr("Quit")
            sequence: "Ctrl+Q"
            onActivated: Qt.quit()
        }
    ]
}
