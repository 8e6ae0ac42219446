import QtQuick
import QtQuick.Controls
import QtQuick3D
import Sortie.Ui

// The flight in three dimensions (docs/view3d.md): the ground, the open route and the fleet's,
// the zones as volumes. Loaded only when the operator switches to 3D (it needs OpenGL). Drag to
// orbit, right-drag (or Shift-drag) to pan, the wheel zooms to the cursor; a click on a waypoint
// selects it. Drawn only when something changes.
Item {
    id: root
    // The open route's document, the fleet's routes (may be null), the zones and the ground: the
    // page hands its graph's (graph.missions.document, graph.fleetRoutes, graph.airspace, graph.elevation).
    required property RouteDocument document
    property FleetRoutes fleetRoutes: null
    required property Airspace airspace
    required property ElevationService elevation
    required property Theme theme
    property alias scene: scene
    // Qt Quick 3D draws through the RHI (OpenGL here): the software scene graph, which the client
    // picks on a machine without a GPU device, cannot draw it (docs/view3d.md).
    readonly property bool canDraw: GraphicsInfo.api !== GraphicsInfo.Software
    property alias exaggeration: scene.exaggeration
    focus: true

    FlightScene {
        id: scene
        document: root.document
        fleetRoutes: root.fleetRoutes
        airspace: root.airspace
        elevation: root.elevation
        theme: root.theme
    }

    View3D {
        objectName: "scene3dView"
        anchors.fill: parent
        visible: root.canDraw
        camera: camera
        environment: SceneEnvironment {
            backgroundMode: SceneEnvironment.Color
            clearColor: root.theme.mapSky
            antialiasingMode: SceneEnvironment.NoAA
        }
        PerspectiveCamera {
            id: camera
            position: scene.camera.position
            rotation: scene.camera.rotation
            fieldOfView: scene.camera.fieldOfView
            clipNear: scene.camera.clipNear
            clipFar: scene.camera.clipFar
        }
        DirectionalLight {
            eulerRotation.x: -55
            eulerRotation.y: -35
            brightness: 1.0
            ambientColor: root.theme.mapAmbient
        }
        Model {
            objectName: "terrainModel"
            geometry: scene.terrain
            materials: DefaultMaterial { vertexColorsEnabled: true; specularAmount: 0; cullMode: Material.NoCulling }
        }
        Model {
            objectName: "routesModel"
            geometry: scene.routes
            materials: DefaultMaterial { vertexColorsEnabled: true; lighting: DefaultMaterial.NoLighting; cullMode: Material.NoCulling }
        }
        Model {
            objectName: "curtainsModel"
            geometry: scene.curtains
            materials: DefaultMaterial { vertexColorsEnabled: true; lighting: DefaultMaterial.NoLighting; cullMode: Material.NoCulling; opacity: 0.99 }
        }
        Model {
            objectName: "zonesModel"
            geometry: scene.zones
            materials: DefaultMaterial { vertexColorsEnabled: true; lighting: DefaultMaterial.NoLighting; cullMode: Material.NoCulling; opacity: 0.99 }
        }
    }

    MouseArea {
        id: mouse
        anchors.fill: parent
        acceptedButtons: Qt.LeftButton | Qt.RightButton | Qt.MiddleButton
        property point last
        property bool moved: false
        onPressed: event => { last = Qt.point(event.x, event.y); moved = false; root.forceActiveFocus() }
        onPositionChanged: event => {
            const dx = event.x - last.x, dy = event.y - last.y
            if (Math.abs(dx) + Math.abs(dy) > 2)
                moved = true
            if ((event.buttons & Qt.LeftButton) && !(event.modifiers & Qt.ShiftModifier))
                scene.camera.orbit(dx, dy)
            else
                scene.camera.pan(dx, dy, root.height)
            last = Qt.point(event.x, event.y)
        }
        onClicked: event => { if (!moved && event.button === Qt.LeftButton) scene.pickAt(event.x, event.y, root.width, root.height) }
        onWheel: wheel => scene.camera.zoomAt(wheel.x, wheel.y, root.width, root.height, Math.pow(0.85, wheel.angleDelta.y / 120))
    }
    Keys.onPressed: event => { event.accepted = scene.camera.key(event.key, event.modifiers, root.height) }

    Column {
        // the legend and the settings over the view's corner
        anchors.left: parent.left
        anchors.bottom: parent.bottom
        anchors.margins: 8
        spacing: 4
        Label {
            visible: !root.canDraw
            text: qsTr("The 3D view needs OpenGL: start Sortie with QSG_RHI_BACKEND=opengl.")
            color: root.theme.windowText
        }
        Label {
            visible: !scene.hasScene
            text: qsTr("Open a route to see it in 3D.")
            color: root.theme.windowText
        }
        Label {
            visible: scene.terrainMissing
            text: qsTr("Purple ground: no elevation data there.")
            color: root.theme.windowText
        }
        Row {
            spacing: 6
            Label { anchors.verticalCenter: parent.verticalCenter; text: qsTr("Vertical exaggeration"); color: root.theme.windowText }
            SpinBox {
                objectName: "exaggerationBox"
                from: 1; to: 10
                value: scene.exaggeration
                onValueModified: scene.exaggeration = value
            }
            Button { text: qsTr("Fit route"); onClicked: scene.fitRoute() }
        }
    }
}
