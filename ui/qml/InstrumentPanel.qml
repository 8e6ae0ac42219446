import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The chosen vehicle's instruments. A value that has not come for a while is greyed.
GroupBox {
    id: panel
    property var vehicle: null
    property DisplayUnits units
    title: vehicle ? qsTr("%1 (%2, %3)").arg(vehicle.name).arg(vehicle.protocol).arg(linkText(vehicle.linkState)) : qsTr("No vehicle chosen")

    function linkText(state) { return ["disconnected", "connecting", "connected", "link lost"][state] || "" }
    function degrees(radians) { return isFinite(radians) ? (radians * 180 / Math.PI).toFixed(0) + "°" : "—" }
    // Reading the vehicle's properties ties the binding to its notifications.
    function stale(field) { return !panel.vehicle || (panel.vehicle.stale, panel.vehicle.altitudeAgl, panel.vehicle.isFieldStale(field)) }

    component Instrument: RowLayout {
        property string caption
        property string value
        property string field
        objectName: "instrument_" + field
        opacity: panel.stale(field) ? 0.35 : 1
        Label { text: parent.caption; Layout.preferredWidth: 120; opacity: 0.8 }
        Label { objectName: "value_" + parent.field; text: parent.value; font.bold: true; Layout.fillWidth: true }
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 2
        Instrument { caption: qsTr("Altitude AGL"); field: "altitudeAgl"; value: panel.vehicle ? panel.units.formatAltitude(panel.vehicle.altitudeAgl) : "—" }
        Instrument { caption: qsTr("Altitude AMSL"); field: "altitudeAmsl"; value: panel.vehicle ? panel.units.formatAltitude(panel.vehicle.altitudeAmsl) : "—" }
        Instrument { caption: qsTr("Ground speed"); field: "groundSpeed"; value: panel.vehicle ? panel.units.formatSpeed(panel.vehicle.groundSpeed) : "—" }
        Instrument { caption: qsTr("Vertical speed"); field: "verticalSpeed"; value: panel.vehicle ? panel.units.formatSpeed(panel.vehicle.verticalSpeed) : "—" }
        Instrument { caption: qsTr("Heading"); field: "heading"; value: panel.vehicle ? panel.degrees(panel.vehicle.heading) : "—" }
        Instrument {
            caption: qsTr("Battery"); field: "batteryRemaining"
            value: panel.vehicle && isFinite(panel.vehicle.batteryRemaining)
                   ? Math.round(panel.vehicle.batteryRemaining * 100) + " %" + (isFinite(panel.vehicle.batteryVoltage) ? "  " + panel.vehicle.batteryVoltage.toFixed(1) + " V" : "")
                   : "—"
        }
        Instrument { caption: qsTr("GPS"); field: "satellites"; value: panel.vehicle ? qsTr("fix %1, %2 satellites").arg(panel.vehicle.gpsFix).arg(panel.vehicle.satellites) : "—" }
        Instrument { caption: qsTr("Mode"); field: "mode"; value: panel.vehicle ? panel.vehicle.mode : "—" }
        Instrument { caption: qsTr("Armed"); field: "armed"; value: panel.vehicle ? (panel.vehicle.armed ? qsTr("ARMED") : qsTr("disarmed")) : "—" }
        Instrument { caption: qsTr("Link"); field: "latitude"; value: panel.vehicle ? panel.linkText(panel.vehicle.linkState) + (panel.vehicle.stale ? qsTr(" (no data)") : "") : "—" }
    }
}
