import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Takes the web map offline: the area (the open route with a margin, the map's view, or one drawn
// on the map: drawRequested, the window draws it and opens the dialog again), the zoom
// range, the tile count and size before starting, the download with its progress, and whether the
// map reads the pack only. OfflineMaps (core/maptiles) decides and downloads; this is a view.
Dialog {
    id: dialog
    required property OfflineMaps offlineMaps
    required property AbstractItemModel routeModel   // the open route (latitude/longitude, polygon roles)
    required property MapView map                    // the map whose view can be the area
    // Its colours; the window hands its own (a dialog shown alone follows the system's).
    property Theme theme: Theme {}
    signal drawRequested()                           // the operator wants to draw the area on the map

    objectName: "offlineMapsDialog"
    title: qsTr("Offline maps")
    modal: true
    parent: Overlay.overlay
    // At the window's right (over the route panel): the map's left part, where an area was just
    // drawn, stays in sight with the area on it.
    x: parent ? Math.max(0, parent.width - width - 20) : 0
    y: parent ? Math.max(0, (parent.height - height) / 2) : 0
    width: Math.min(parent ? parent.width - 80 : 600, 600)
    standardButtons: Dialog.Close

    onAboutToShow: {
        minZoom.value = offlineMaps.minimumZoom
        maxZoom.value = offlineMaps.maximumZoom
        margin.value = offlineMaps.marginMetres
        packField.text = offlineMaps.packFile
        attributionField.text = offlineMaps.attribution
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 6
        Label {
            textFormat: Text.PlainText
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            text: dialog.offlineMaps.urlTemplate.length > 0
                  ? qsTr("From %1").arg(dialog.offlineMaps.urlTemplate)
                  : qsTr("Choose a web tile server in Map source first.")
        }
        RowLayout {
            Button {
                objectName: "routeAreaButton"
                text: qsTr("The open route")
                onClicked: dialog.offlineMaps.useRouteArea(dialog.routeModel)
            }
            Label { textFormat: Text.PlainText; text: qsTr("and") }
            SpinBox {
                id: margin
                objectName: "marginBox"
                from: 0; to: 50000; stepSize: 100
                editable: true
                onValueModified: dialog.offlineMaps.marginMetres = value
            }
            Label { textFormat: Text.PlainText; text: qsTr("m around it") }
        }
        RowLayout {
            Button {
                objectName: "viewAreaButton"
                text: qsTr("The map's view")
                onClicked: dialog.offlineMaps.useViewArea(dialog.map.toCoordinate(Qt.point(0, dialog.map.height)),
                                                         dialog.map.toCoordinate(Qt.point(dialog.map.width, 0)))
            }
            Button {
                objectName: "drawAreaButton"
                text: qsTr("Draw an area")
                onClicked: { dialog.close(); dialog.drawRequested() }
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Click its corners on the map, or Shift+drag a box")
            }
        }
        Label {
            textFormat: Text.PlainText
            objectName: "areaLabel"
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            text: dialog.offlineMaps.areaText
        }
        RowLayout {
            Label { textFormat: Text.PlainText; text: qsTr("Zoom from") }
            SpinBox {
                id: minZoom
                objectName: "minZoomBox"
                from: 0; to: 22
                onValueModified: dialog.offlineMaps.minimumZoom = value
            }
            Label { textFormat: Text.PlainText; text: qsTr("to") }
            SpinBox {
                id: maxZoom
                objectName: "maxZoomBox"
                from: 0; to: 22
                onValueModified: dialog.offlineMaps.maximumZoom = value
            }
        }
        Label {
            textFormat: Text.PlainText
            objectName: "estimateLabel"
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            text: dialog.offlineMaps.estimateText
        }
        GridLayout {
            columns: 2
            Layout.fillWidth: true
            Label { textFormat: Text.PlainText; text: qsTr("Pack file") }
            TextField {
                id: packField
                objectName: "packField"
                Layout.fillWidth: true
                selectByMouse: true
                onEditingFinished: dialog.offlineMaps.packFile = text
            }
            Label { textFormat: Text.PlainText; text: qsTr("Attribution") }
            TextField {
                id: attributionField
                objectName: "attributionField"
                Layout.fillWidth: true
                selectByMouse: true
                placeholderText: qsTr("As the provider's usage policy asks, e.g. © OpenStreetMap contributors")
                onEditingFinished: dialog.offlineMaps.attribution = text
            }
        }
        CheckBox {
            objectName: "cacheOnlyBox"
            text: qsTr("Cache only: the map never uses the network (the pack, then the disk cache)")
            checked: dialog.offlineMaps.cacheOnly
            onToggled: dialog.offlineMaps.cacheOnly = checked
        }
        ProgressBar {
            objectName: "prefetchProgress"
            Layout.fillWidth: true
            value: dialog.offlineMaps.progress
        }
        Label {
            textFormat: Text.PlainText
            objectName: "progressLabel"
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            text: dialog.offlineMaps.progressText
        }
        Label {
            textFormat: Text.PlainText
            objectName: "problemLabel"
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            color: dialog.theme.problemText
            visible: text.length > 0
            text: dialog.offlineMaps.problem
        }
        ListView {
            objectName: "failureList"
            Layout.fillWidth: true
            Layout.preferredHeight: Math.min(contentHeight, 80)
            clip: true
            model: dialog.offlineMaps.failures
            delegate: Label { textFormat: Text.PlainText; required property string modelData; text: modelData; font.pixelSize: 11 }
        }
        RowLayout {
            Button {
                objectName: "startButton"
                text: qsTr("Download")
                enabled: dialog.offlineMaps.canStart
                onClicked: dialog.offlineMaps.start()
            }
            Button {
                objectName: "pauseButton"
                text: dialog.offlineMaps.paused ? qsTr("Resume") : qsTr("Pause")
                enabled: dialog.offlineMaps.running
                onClicked: dialog.offlineMaps.paused ? dialog.offlineMaps.resume() : dialog.offlineMaps.pause()
            }
            Button {
                objectName: "stopButton"
                text: qsTr("Stop")
                enabled: dialog.offlineMaps.running
                onClicked: dialog.offlineMaps.stop()
            }
        }
    }
}
