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
    property Airspace airspace: null          // where the route crosses zones, drawn with their limits
    property RouteEndurance endurance: null   // its battery changes and point of no return, marked
    property Theme theme: null                // its colours (null: the light scheme's, for a panel shown alone)
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
        endurance: panel.endurance
        theme: panel.theme
    }
    ZoneProfileOverlay {
        objectName: "zoneProfile"
        anchors.fill: view
        view: view
        airspace: panel.airspace
    }
}
