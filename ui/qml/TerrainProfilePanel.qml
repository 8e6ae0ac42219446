import QtQuick
import QtQml.Models
import Sortie.Ui

// The elevation profile of the route being edited, under the map: the view (ElevationProfileView)
// over its coalesced model (TerrainProfileModel), fed by the client's ElevationService.
Item {
    id: panel
    required property AbstractItemModel routeModel
    required property ItemSelectionModel selectionModel
    required property ElevationService elevation
    property var zoneCrossings: []   // Airspace.crossings: where the route crosses zones, drawn with their limits
    property var markers: []   // JS objects {latitude, longitude, label, color}: ElevationProfileView.markers
    property alias view: view
    property alias profile: profile
    implicitHeight: 170

    TerrainProfileModel {
        id: profile
        routeModel: panel.routeModel
        service: panel.elevation
    }
    ElevationProfileView {
        id: view
        objectName: "elevationProfile"
        anchors.fill: parent
        model: profile
        selectionModel: panel.selectionModel
        markers: panel.markers
        textColor: palette.windowText
        backgroundColor: palette.base
    }
    ZoneProfileOverlay {
        objectName: "zoneProfile"
        anchors.fill: view
        view: view
        crossings: panel.zoneCrossings
    }
}
