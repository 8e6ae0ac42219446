import QtQuick
import QtQuick.Controls
import QtQuick.Layouts

// The selected area scan's camera and overlaps; the planned transects show on the map.
GroupBox {
    id: editor
    required property var doc
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
                if (!isNaN(v) && v !== editor.parameters[parent.key])
                    editor.doc.editor.setParameter([editor.doc.currentRow], parent.key, v)
            }
        }
        Label { text: parent.unit; opacity: 0.7 }
    }

    ColumnLayout {
        anchors.fill: parent
        Label { text: editor.parameters.camera !== undefined ? qsTr("Camera: %1").arg(editor.parameters.camera) : "" }
        Field { label: qsTr("Altitude"); key: "height"; unit: "m" }
        Field { label: qsTr("Front overlap"); key: "overlapForward"; unit: "%" }
        Field { label: qsTr("Side overlap"); key: "overlapSide"; unit: "%" }
        Field { label: qsTr("Direction"); key: "directionAngle"; unit: "°" }
        Label {
            visible: editor.doc && editor.doc.scanProblem.length > 0
            text: editor.doc ? editor.doc.scanProblem : ""
            color: "#e53935"
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
    }
}
