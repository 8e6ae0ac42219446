import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The chosen vehicle's instruments: attitude and heading (with the bearings to home and to the
// next waypoint), then its readings, the mission's progress and the battery against its levels.
// A value that has not come for a while is greyed. FlightStatus derives, DisplayUnits formats;
// this view only lays them out.
GroupBox {
    id: panel
    required property Theme theme
    required property Vehicle vehicle      // null: none chosen
    required property DisplayUnits units
    required property EnduranceAdvisory advisory   // for the same vehicle: battery at the end, energy home
    readonly property alias status: status
    title: vehicle ? qsTr("%1 (%2, %3)").arg(vehicle.name).arg(vehicle.protocol).arg(units.formatLinkState(vehicle.linkState))
                   : qsTr("No vehicle chosen")

    FlightStatus {
        id: status
        vehicle: panel.vehicle
    }

    // Reading the vehicle's properties ties the binding to its notifications.
    function stale(field) { return !panel.vehicle || (panel.vehicle.stale, panel.vehicle.altitudeAgl, panel.vehicle.isFieldStale(field)) }
    readonly property color batteryColor: status.batteryState === FlightStatus.Critical ? panel.theme.problemText
                                        : status.batteryState === FlightStatus.Low ? panel.theme.warningText : palette.windowText

    component Instrument: RowLayout {
        property string caption
        property string value
        property string field
        property string staleField: field // greyed when this telemetry field goes stale
        property color valueColor: panel.palette.windowText
        objectName: "instrument_" + field
        opacity: panel.stale(staleField) ? 0.35 : 1
        spacing: 6
        Label { textFormat: Text.PlainText; text: parent.caption; Layout.preferredWidth: 96; elide: Text.ElideRight; opacity: 0.8 }
        Label {
            textFormat: Text.PlainText
            objectName: "value_" + parent.field
            text: parent.value
            color: parent.valueColor
            font.bold: true
            elide: Text.ElideRight
            Layout.fillWidth: true
        }
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 2
        RowLayout {
            Layout.fillWidth: true
            Layout.bottomMargin: 4
            spacing: 6
            AttitudeIndicator {
                objectName: "attitudeIndicator"
                Layout.fillWidth: true
                Layout.preferredHeight: width
                Layout.maximumHeight: 160
                roll: status.roll
                pitch: status.pitch
                theme: panel.theme
            }
            HeadingCompass {
                objectName: "headingCompass"
                Layout.fillWidth: true
                Layout.preferredHeight: width
                Layout.maximumHeight: 160
                heading: panel.vehicle ? panel.vehicle.heading : NaN
                bearingToHome: status.bearingToHome
                bearingToNext: status.bearingToNext
                theme: panel.theme
            }
        }
        Instrument { caption: qsTr("Altitude AGL"); field: "altitudeAgl"; value: panel.vehicle ? panel.units.formatAltitude(panel.vehicle.altitudeAgl) : "—" }
        Instrument { caption: qsTr("Altitude AMSL"); field: "altitudeAmsl"; value: panel.vehicle ? panel.units.formatAltitude(panel.vehicle.altitudeAmsl) : "—" }
        Instrument { caption: qsTr("Ground speed"); field: "groundSpeed"; value: panel.vehicle ? panel.units.formatSpeed(panel.vehicle.groundSpeed) : "—" }
        Instrument { caption: qsTr("Vertical speed"); field: "verticalSpeed"; value: panel.vehicle ? panel.units.formatSpeed(panel.vehicle.verticalSpeed) : "—" }
        Instrument { caption: qsTr("Heading"); field: "heading"; value: panel.vehicle ? panel.units.formatHeading(panel.vehicle.heading) : "—" }
        Instrument {
            caption: qsTr("Battery"); field: "batteryVoltage"
            value: panel.vehicle ? panel.units.formatBattery(panel.vehicle.batteryVoltage, panel.vehicle.batteryRemaining) : "—"
            valueColor: panel.batteryColor
        }
        Instrument { caption: qsTr("GPS"); field: "satellites"; value: panel.vehicle ? qsTr("fix %1, %2 satellites").arg(panel.vehicle.gpsFix).arg(panel.vehicle.satellites) : "—" }
        Instrument { caption: qsTr("Mode"); field: "mode"; value: panel.vehicle ? panel.vehicle.mode : "—" }
        Instrument { caption: qsTr("Armed"); field: "armed"; value: panel.vehicle ? (panel.vehicle.armed ? qsTr("ARMED") : qsTr("disarmed")) : "—" }
        Instrument {
            caption: qsTr("Link"); field: "latitude"
            value: !panel.vehicle ? "—"
                   : panel.vehicle.stale ? panel.units.formatLinkState(panel.vehicle.linkState) + qsTr(" (no data)")
                   : isFinite(status.telemetryRate) ? qsTr("%1, %2 Hz").arg(panel.units.formatLinkState(panel.vehicle.linkState)).arg(status.telemetryRate.toFixed(0))
                   : panel.units.formatLinkState(panel.vehicle.linkState)
        }
        Instrument { caption: qsTr("Flight time"); field: "armedTime"; staleField: "armed"; value: panel.units.formatDuration(status.flightSeconds) }
        Instrument { caption: qsTr("To home"); field: "home"; staleField: "latitude"; value: panel.units.formatDistance(status.distanceToHome) }
        Instrument { caption: qsTr("Mission"); field: "mission"; staleField: "latitude"; value: panel.vehicle ? status.progressText : "—" }
        Instrument {
            caption: qsTr("Left"); field: "missionLeft"; staleField: "latitude"
            value: status.missionFlying ? qsTr("%1, %2").arg(panel.units.formatDistance(status.distanceLeft)).arg(panel.units.formatDuration(status.timeLeft)) : "—"
        }
        Label {
            textFormat: Text.PlainText
            objectName: "enduranceLine"
            Layout.fillWidth: true
            text: panel.advisory.summary
            wrapMode: Text.Wrap
            font.bold: panel.advisory.level === EnduranceAdvisory.Amber || panel.advisory.level === EnduranceAdvisory.Red
            color: panel.advisory.level === EnduranceAdvisory.Red ? panel.theme.problemText
                 : panel.advisory.level === EnduranceAdvisory.Amber ? panel.theme.warningText : panel.palette.windowText
            ToolTip.visible: hoverArea.hovered && panel.advisory.problem.length > 0
            ToolTip.text: panel.advisory.problem
            HoverHandler { id: hoverArea }
        }
    }
}
