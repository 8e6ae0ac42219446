import QtQuick
import QtQuick.Controls
import Sortie.Ui

// A map with its furniture: zoom buttons, scale bar, attribution, rubber band. Layers declared
// inside a MapPane sit above the map and should say `map: pane.map; anchors.fill: parent`.
// The pane owns its own tile source, chosen by `mapSource`. The graticule labels the top and left
// edges: controls placed on the map keep `controlsTop` / `controlsLeft` from them, as the pane's
// own do, so that none covers a label.
Item {
    id: pane
    property alias map: mapView
    required property DisplayUnits units
    property string mapSource: "offline"        // "offline", "xyz" or "mbtiles"
    property string tileUrlTemplate: ""
    property string mbtilesFile: ""
    property string tilePackFile: ""    // tiles taken offline for the web source (OfflineMaps)
    property bool tilesCacheOnly: false // the web source never uses the network
    property string orthophotoFile: ""  // the operator's orthophoto over the base map (empty: none)
    property real orthophotoOpacity: 0.8
    // The map's colours and the furniture's; the page hands its own (a pane shown alone follows the system's).
    property Theme theme: Theme {}
    default property alias layers: overlay.data
    readonly property real controlsTop: mapView.labelBandTop + 6
    readonly property real controlsLeft: mapView.labelBandLeft + 6

    XyzTileSource {
        id: webTiles
        urlTemplate: pane.mapSource === "xyz" ? pane.tileUrlTemplate : ""
        packFile: pane.mapSource === "xyz" ? pane.tilePackFile : ""
        cacheOnly: pane.tilesCacheOnly
    }
    MbTilesTileSource {
        id: fileTiles
        file: pane.mapSource === "mbtiles" ? pane.mbtilesFile : ""
    }

    MapView {
        id: mapView
        objectName: "mapView"
        anchors.fill: parent
        theme: pane.theme
        tileSource: pane.mapSource === "xyz" ? webTiles : pane.mapSource === "mbtiles" ? fileTiles : null
    }

    OrthophotoLayer {
        // Above the base map, below every layer the page declares (zones, routes, vehicles).
        id: orthophoto
        objectName: "orthophotoLayer"
        anchors.fill: parent
        map: mapView
        file: pane.orthophotoFile
        opacity: pane.orthophotoOpacity
        visible: valid
    }

    Item {
        id: overlay
        anchors.fill: parent
    }

    Rectangle {
        objectName: "rubberBand"
        visible: mapView.selectionRect.width > 0
        x: mapView.selectionRect.x
        y: mapView.selectionRect.y
        width: mapView.selectionRect.width
        height: mapView.selectionRect.height
        color: Qt.rgba(pane.theme.accent.r, pane.theme.accent.g, pane.theme.accent.b, 0.15)
        border.color: pane.theme.accent
    }

    Column {
        objectName: "zoomButtons"
        anchors.right: parent.right
        anchors.top: parent.top
        anchors.rightMargin: 10
        anchors.topMargin: pane.controlsTop
        spacing: 4
        RoundButton {
            objectName: "zoomInButton"
            text: "+"
            focusPolicy: Qt.NoFocus
            onClicked: mapView.zoomIn()
            ToolTip.visible: hovered
            ToolTip.text: qsTr("Zoom in (+, wheel)")
        }
        RoundButton {
            objectName: "zoomOutButton"
            text: "−"
            focusPolicy: Qt.NoFocus
            onClicked: mapView.zoomOut()
            ToolTip.visible: hovered
            ToolTip.text: qsTr("Zoom out (−, wheel)")
        }
    }

    Rectangle {
        objectName: "scaleBarFrame"
        anchors.left: parent.left
        anchors.bottom: parent.bottom
        anchors.leftMargin: pane.controlsLeft
        anchors.bottomMargin: 8
        width: scaleBar.width + 8
        height: scaleBar.height + 4
        radius: 3
        color: pane.theme.overlay
        MapScaleBar {
            id: scaleBar
            objectName: "scaleBar"
            anchors.centerIn: parent
            width: 140
            height: 26
            map: mapView
            imperial: pane.units.imperial
            color: pane.theme.overlayText
        }
    }

    Label {
        textFormat: Text.PlainText
        objectName: "attributionLabel"
        anchors.right: parent.right
        anchors.bottom: parent.bottom
        anchors.margins: 4
        text: mapView.attribution
        font.pixelSize: 10
        padding: 2
        color: pane.theme.overlayText
        background: Rectangle { color: pane.theme.overlay }
    }
}
