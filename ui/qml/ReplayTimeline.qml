import QtQuick
import QtQuick.Controls
import QtQuick.Dialogs
import QtQuick.Layouts
import Sortie.Ui

// The replay timeline under the fly view: open a flight log, play or pause it, choose a speed,
// scrub, and jump to its events (marked on the bar). While a log plays, a banner says so: replayed
// vehicles are never taken for live ones. The ReplayController decides everything; this is a view.
ToolBar {
    id: bar
    required property Theme theme
    required property ReplayController replay
    // The connected server's history, replayed in the same controller.
    required property ServerHistoryRequest serverHistory
    // The flight's photos, placed on the log of the vehicle chosen in the fly view (vehicleIndex).
    required property PhotoSurvey photos
    required property DisplayUnits units
    property int vehicleIndex: -1
    property string exportMessage

    FileDialog {
        id: openDialog
        title: qsTr("Open a flight log")
        nameFilters: [qsTr("Flight logs (*.sortielog)"), qsTr("All files (*)")]
        onAccepted: bar.replay.open(selectedFile.toString())
    }
    FileDialog {
        id: exportDialog
        property string format: "gpx"
        title: qsTr("Export tracks")
        fileMode: FileDialog.SaveFile
        nameFilters: [format.toUpperCase() + " (*." + format + ")"]
        onAccepted: bar.exportMessage = bar.replay.exportTracks(format, selectedFile) || qsTr("Exported to %1.").arg(selectedFile)
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 2
        RowLayout {
            Layout.fillWidth: true
            spacing: 8
            Button {
                objectName: "openLogButton"
                text: qsTr("Open log…")
                onClicked: openDialog.open()
            }
            Button {
                objectName: "serverHistoryButton"
                text: qsTr("Server history…")
                onClicked: { historyDialog.active = true; historyDialog.item.open() }
                Loader { // made when first opened: the start-up does not pay for it
                    id: historyDialog
                    active: false
                    sourceComponent: ServerHistoryDialog { theme: bar.theme; request: bar.serverHistory }
                }
            }
            Rectangle {
                objectName: "replayBanner"
                visible: bar.replay.active
                color: bar.theme.replay
                radius: 3
                implicitWidth: bannerText.implicitWidth + 12
                implicitHeight: bannerText.implicitHeight + 4
                Label {
                    textFormat: Text.PlainText
                    id: bannerText
                    anchors.centerIn: parent
                    color: bar.theme.onReplay
                    font.bold: true
                    text: qsTr("REPLAY — %1").arg(bar.replay.spanText)
                }
            }
            Button {
                objectName: "playButton"
                visible: bar.replay.active
                text: bar.replay.playing ? qsTr("Pause") : qsTr("Play")
                onClicked: bar.replay.togglePlaying()
            }
            ToolButton {
                objectName: "previousEventButton"
                visible: bar.replay.active
                // An icon: the fonts Debian ships by default have no glyph for ⏮.
                Accessible.name: ToolTip.text
                padding: 6
                contentItem: TintedIcon {
                    name: "media-skip-backward"
                    color: parent.palette.buttonText
                    implicitWidth: bar.theme.iconSize
                    implicitHeight: bar.theme.iconSize
                }
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Previous event")
                onClicked: bar.replay.previousEvent()
            }
            ToolButton {
                objectName: "nextEventButton"
                visible: bar.replay.active
                // An icon: the fonts Debian ships by default have no glyph for ⏭.
                Accessible.name: ToolTip.text
                padding: 6
                contentItem: TintedIcon {
                    name: "media-skip-forward"
                    color: parent.palette.buttonText
                    implicitWidth: bar.theme.iconSize
                    implicitHeight: bar.theme.iconSize
                }
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Next event")
                onClicked: bar.replay.nextEvent()
            }
            ComboBox {
                objectName: "speedBox"
                visible: bar.replay.active
                Layout.preferredWidth: 96 // "16×" fits; the implicit width is the style's 140
                model: bar.replay.speeds
                displayText: bar.replay.speed + "×"
                delegate: ItemDelegate {
                    required property var modelData
                    text: modelData + "×"
                    width: ListView.view.width
                }
                onActivated: index => bar.replay.speed = bar.replay.speeds[index]
            }
        }
        // The second row: where the replay is, and what to do with the log. Two rows keep the bar
        // inside the map's column at 1280 px.
        RowLayout {
            Layout.fillWidth: true
            visible: bar.replay.active
            spacing: 8
            ComboBox {
                objectName: "eventBox"
                visible: bar.replay.active
                Layout.preferredWidth: 260
                Layout.minimumWidth: 140
                Layout.fillWidth: true
                model: bar.replay.events
                textRole: "text"
                displayText: qsTr("Jump to event (%1)").arg(bar.replay.events.count)
                delegate: ItemDelegate {
                    required property var model // the event's roles; an ItemDelegate's own `text` is final
                    width: ListView.view.width
                    text: model.timeText + "  " + (model.vehicle.length > 0 ? model.vehicle + ": " : "") + model.text
                }
                onActivated: index => bar.replay.jumpToEvent(index)
            }
            Label {
                textFormat: Text.PlainText
                objectName: "historyLoadingLabel"
                visible: bar.replay.active && !bar.replay.historyLoaded
                text: qsTr("Loading plots…")
                opacity: 0.7
            }
            Label {
                textFormat: Text.PlainText
                objectName: "positionLabel"
                visible: bar.replay.active
                text: bar.replay.positionText
                Layout.fillWidth: true
                elide: Text.ElideRight
            }
            Button {
                objectName: "exportButton"
                visible: bar.replay.active
                text: qsTr("Export…")
                onClicked: exportMenu.open()
                Menu {
                    id: exportMenu
                    Repeater {
                        model: ["gpx", "kml", "csv"] // i18n: not text (file formats, shown as GPX, KML, CSV)
                        MenuItem {
                            required property string modelData
                            text: modelData.toUpperCase()
                            onTriggered: { exportDialog.format = modelData; exportDialog.open() }
                        }
                    }
                }
            }
            Button {
                objectName: "photosButton"
                visible: bar.replay.active
                text: qsTr("Photos…")
                onClicked: { photosDialog.active = true; photosDialog.item.open() }
                Loader { // made when first opened
                    id: photosDialog
                    active: false
                    sourceComponent: PhotosDialog { theme: bar.theme; units: bar.units; survey: bar.photos; vehicleIndex: bar.vehicleIndex }
                }
            }
            Button {
                objectName: "closeLogButton"
                visible: bar.replay.active
                text: qsTr("Back to live")
                onClicked: bar.replay.close()
            }
        }
        Item {
            visible: bar.replay.active
            Layout.fillWidth: true
            implicitHeight: slider.implicitHeight
            Slider {
                id: slider
                objectName: "timelineSlider"
                anchors.fill: parent
                from: 0
                to: 1
                value: bar.replay.progress
                onMoved: bar.replay.progress = value
            }
            Repeater {
                model: bar.replay.events
                Rectangle {
                    required property real fraction
                    required property bool failed
                    x: slider.leftPadding + fraction * slider.availableWidth - 1
                    y: 2
                    width: 2
                    height: 6
                    color: failed ? bar.theme.problem : bar.theme.replay
                }
            }
        }
        Label {
            textFormat: Text.PlainText
            id: exportResult
            objectName: "replayMessage"
            visible: text.length > 0
            text: [bar.replay.errorString, bar.replay.warning, bar.exportMessage].filter(t => t.length > 0).join("\n")
            color: bar.replay.errorString.length > 0 || bar.replay.warning.length > 0 ? bar.theme.problemText : palette.windowText
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
    }
}
