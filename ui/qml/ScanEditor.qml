import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The selected area scan's camera and overlaps; the planned transects show on the map.
GroupBox {
    id: editor
    required property RouteDocument doc
    readonly property var parameters: doc ? doc.scanParameters : ({})
    title: qsTr("Area scan")

    component Field: RowLayout {
        property alias label: caption.text
        property string key
        property string unit
        Label { id: caption; Layout.preferredWidth: 110 }
        TextField {
            objectName: "scan_" + parent.key
            text: editor.parameters[parent.key] !== undefined ? Number(editor.parameters[parent.key]).toFixed(1) : ""
            Layout.preferredWidth: 70
            selectByMouse: true
            onEditingFinished: {
                const v = Number(text)
                if (!isNaN(v) && v !== editor.parameters[parent.key]) {
                    const change = {}
                    change[parent.key] = v
                    editor.doc.setScanParameters(editor.doc.currentRow, change)
                }
            }
        }
        Label { text: parent.unit; opacity: 0.7 }
    }

    ColumnLayout {
        anchors.fill: parent
        Label { text: editor.parameters.cameraName !== undefined ? qsTr("Camera: %1").arg(editor.parameters.cameraName) : "" }
        Field { label: qsTr("Altitude"); key: "altitude"; unit: "m" }
        Field { label: qsTr("Front overlap"); key: "frontOverlapPercent"; unit: "%" }
        Field { label: qsTr("Side overlap"); key: "sideOverlapPercent"; unit: "%" }
        Field { label: qsTr("Direction"); key: "directionDeg"; unit: "°" }
        Label {
            visible: editor.doc && editor.doc.scanProblem.length > 0
            text: editor.doc ? editor.doc.scanProblem : ""
            color: "#e53935"
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
    }
}
