import QtQuick
import QtQuick.Controls
import QtQuick.Dialogs
import QtQuick.Layouts
import Sortie.Ui

// Beside the map: which route, what to do with it (save, undo, process, upload, files, area
// scan), how it stands (progress, messages, statistics, validation) and its table.
Pane {
    id: panel
    required property Theme theme
    required property MissionController missions
    readonly property RoutePreparation preparation: missions.preparation
    readonly property bool uploading: preparation.uploader.busy && !preparation.uploader.asking
    required property RouteDocument doc          // the missions' document
    required property DisplayUnits units
    required property AbstractItemModel routeModel // the list model the table shows
    required property TerrainProfileModel terrain // ground and heights per row
    required property RouteEndurance endurance
    property RouteDeconfliction deconfliction: null  // conflicts with the fleet's other routes; null without vehicles
    property Airspace airspace: null                 // an airspace issue also chooses its zone
    required property int waypointCount
    required property bool scanning              // the area-scan tool is on
    signal scanToggled(bool on)
    // The width at which the waypoint table's headers show whole (they are longer in some languages).
    readonly property real neededWidth: waypointTable.neededWidth + leftPadding + rightPadding
    padding: 8
    contentWidth: availableWidth // the content follows the panel's width, not its own wishes
    clip: true

    FileDialog {
        id: importDialog
        title: qsTr("Import a route")
        nameFilters: [qsTr("Routes (*.sortie *.plan *.waypoints *.txt *.kml *.kmz)"), qsTr("All files (*)")]
        onAccepted: panel.doc.importFile(selectedFile)
    }
    FileDialog {
        id: profileDialog
        title: qsTr("The vehicle's energy profile")
        nameFilters: [qsTr("Energy profiles (*.json)"), qsTr("All files (*)")]
        onAccepted: panel.endurance.loadProfileFile(selectedFile)
    }
    FileDialog {
        id: exportDialog
        title: qsTr("Export the route")
        fileMode: FileDialog.SaveFile
        nameFilters: [qsTr("Sortie (*.sortie)"), qsTr("QGroundControl plan (*.plan)"), qsTr("Waypoint list (*.waypoints)"), qsTr("KML (*.kml)"), qsTr("DJI Pilot 2 route, WPML (*.kmz)")]
        onAccepted: panel.doc.exportFile(selectedFile)
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 6

        RowLayout {
            Layout.fillWidth: true
            ComboBox {
                id: routePicker
                objectName: "routePicker"
                Layout.fillWidth: true
                Layout.preferredWidth: 120
                model: panel.missions.routes
                textRole: "name"
                valueRole: "objectId"
                displayText: currentIndex < 0 ? qsTr("Choose a route…") : currentText
            }
            Button {
                objectName: "openRouteButton"
                text: qsTr("Open")
                enabled: routePicker.currentIndex >= 0
                onClicked: panel.missions.openRoute(routePicker.currentValue)
            }
        }

        Flow {
            Layout.fillWidth: true
            spacing: 4
            Button { objectName: "saveButton"; text: qsTr("Save"); enabled: panel.missions.canSave; onClicked: panel.missions.save()
                     ToolTip.visible: hovered; ToolTip.text: qsTr("Save on the server, under its lock (Ctrl+S)") }
            Button { objectName: "undoButton"; text: qsTr("Undo"); enabled: panel.doc.canUndo; onClicked: panel.doc.undo()
                     ToolTip.visible: hovered; ToolTip.text: qsTr("Undo %1 (Ctrl+Z)").arg(panel.doc.undoText) }
            Button { objectName: "redoButton"; text: qsTr("Redo"); enabled: panel.doc.canRedo; onClicked: panel.doc.redo()
                     ToolTip.visible: hovered; ToolTip.text: qsTr("Redo %1 (Ctrl+Shift+Z)").arg(panel.doc.redoText) }
            Button { text: qsTr("Delete"); enabled: panel.doc.selectedRows.length > 0; onClicked: panel.doc.editor.removeRows(panel.doc.selectedRows)
                     ToolTip.visible: hovered; ToolTip.text: qsTr("Delete the selected waypoints (Del)") }
            Button { objectName: "scanToolButton"; text: qsTr("Area scan"); checkable: true; checked: panel.scanning
                     onToggled: panel.scanToggled(checked)
                     ToolTip.visible: hovered; ToolTip.text: qsTr("Draw an area to scan: click its corners on the map") }
            Button { text: qsTr("Import…"); onClicked: importDialog.open() }
            Button { text: qsTr("Export…"); onClicked: exportDialog.open() }
            // What the server's route processing refuses the route for (HCI checkAerodromeNfz /
            // checkCustomNfz): a menu, so the waypoint table keeps its room.
            Button { objectName: "nfzChecksButton"; text: qsTr("Zone checks…"); onClicked: nfzChecksMenu.open()
                     ToolTip.visible: hovered; ToolTip.text: qsTr("Which no-fly zones the server's processing refuses the route for")
                Menu {
                    id: nfzChecksMenu
                    y: parent.height
                    MenuItem { objectName: "checkAerodromeNfz"; text: qsTr("Refuse crossing aerodrome zones"); checkable: true
                               checked: panel.doc.model.checkAerodromeNfz; onToggled: panel.doc.editor.setCheckAerodromeNfz(checked) }
                    MenuItem { objectName: "checkCustomNfz"; text: qsTr("Refuse crossing custom zones"); checkable: true
                               checked: panel.doc.model.checkCustomNfz; onToggled: panel.doc.editor.setCheckCustomNfz(checked) }
                }
            }
        }

        RowLayout {
            Layout.fillWidth: true
            Button { objectName: "processButton"; text: qsTr("Process")
                     enabled: vehiclePicker.currentIndex >= 0 && !panel.preparation.processing
                     onClicked: panel.preparation.process()
                     ToolTip.visible: hovered; ToolTip.text: qsTr("Prepare the route for the chosen vehicle, as the upload will, and show what it would fly (Ctrl+P)") }
            ComboBox {
                id: vehiclePicker
                objectName: "vehiclePicker"
                Layout.fillWidth: true
                Layout.preferredWidth: 120
                displayText: currentIndex < 0 ? qsTr("Vehicle…") : currentText
                model: panel.preparation.fleet // every vehicle, HCI and VCI
                textRole: "name"
                valueRole: "vehicleId"
                onCurrentValueChanged: panel.preparation.vehicleId = currentIndex >= 0 ? currentValue : ""
                // A vehicle chosen elsewhere (a resumed mission opened for its vehicle) shows here.
                function follow() {
                    const at = indexOfValue(panel.preparation.vehicleId)
                    if (at !== currentIndex && (at >= 0 || panel.preparation.vehicleId === ""))
                        currentIndex = at
                }
                Connections {
                    target: panel.preparation
                    function onVehicleIdChanged() { vehiclePicker.follow() }
                }
                onCountChanged: follow()
            }
            Button { objectName: "uploadButton"; text: qsTr("Upload"); enabled: vehiclePicker.currentIndex >= 0 && !panel.preparation.uploader.busy
                     onClicked: panel.preparation.upload() }
            Button { objectName: "cancelUploadButton"; text: qsTr("Cancel"); visible: panel.preparation.uploader.canCancel
                     onClicked: panel.preparation.uploader.cancel() }
        }

        OpenQuestion {
            missions: panel.missions
        }

        UploadQuestion {
            uploader: panel.preparation.uploader
            onSaveAndUpload: panel.preparation.saveAndUpload()
        }

        Frame {
            objectName: "conflictBanner"
            visible: panel.missions.conflict
            Layout.fillWidth: true
            background: Rectangle { color: panel.theme.noticeBackground; border.color: panel.theme.noticeBorder; radius: 3 }
            ColumnLayout {
                anchors.fill: parent
                Label { textFormat: Text.PlainText; text: panel.missions.conflictText; wrapMode: Text.Wrap; Layout.fillWidth: true; color: panel.theme.noticeText }
                Label {
                    textFormat: Text.PlainText
                    text: qsTr("Yours (version %1, edited) against theirs (version %2, grey on the map):")
                          .arg(panel.missions.conflictDetails.yourVersion)
                          .arg(panel.missions.conflictDetails.theirVersion)
                    wrapMode: Text.Wrap; Layout.fillWidth: true; color: panel.theme.noticeText; font.bold: true
                }
                ListView {
                    objectName: "conflictChanges"
                    Layout.fillWidth: true
                    Layout.preferredHeight: Math.min(contentHeight, 110)
                    clip: true
                    model: panel.missions.conflictDetails.changes
                    delegate: Label { textFormat: Text.PlainText; required property string modelData; text: "• " + modelData; color: panel.theme.noticeText; wrapMode: Text.Wrap; width: ListView.view.width }
                }
                Label {
                    textFormat: Text.PlainText
                    visible: panel.missions.conflictDetails.theirEdits.length > 0
                    text: qsTr("They changed: %1").arg(panel.missions.conflictDetails.theirEdits.join(", "))
                    wrapMode: Text.Wrap; Layout.fillWidth: true; color: panel.theme.noticeText; font.pointSize: 8
                }
                RowLayout {
                    Button { objectName: "keepMineButton"; text: qsTr("Keep mine (overwrite theirs)"); onClicked: panel.missions.keepMine() }
                    Button { objectName: "takeTheirsButton"; text: qsTr("Take theirs (undo brings mine back)"); onClicked: panel.missions.takeTheirs() }
                }
            }
        }

        ColumnLayout {
            // The library's work (open, save) or an upload's, whichever runs: never both at once.
            readonly property QtObject source: panel.uploading ? panel.preparation.uploader : panel.missions
            visible: panel.missions.busy || panel.uploading
            Layout.fillWidth: true
            Label { textFormat: Text.PlainText; text: parent.source.activity + "…" }
            ProgressBar {
                objectName: "progressBar"
                Layout.fillWidth: true
                indeterminate: parent.source.progressMaximum <= 0
                from: 0
                to: Math.max(1, parent.source.progressMaximum)
                value: parent.source.progressValue
            }
        }

        Label {
            textFormat: Text.PlainText
            objectName: "preparationMessage"
            visible: text.length > 0
            text: panel.preparation.message
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }

        Label {
            textFormat: Text.PlainText
            objectName: "missionMessage"
            visible: text.length > 0
            text: [panel.missions.message, panel.doc.message].filter(m => m.length > 0).join("\n")
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }

        GridLayout {
            objectName: "statistics"
            columns: 4
            Layout.fillWidth: true
            Label { textFormat: Text.PlainText; text: qsTr("Length") ; opacity: 0.7 }
            Label { textFormat: Text.PlainText; text: panel.units.formatDistance(panel.doc.analyzer.lengthMeters) }
            Label { textFormat: Text.PlainText; text: qsTr("Time"); opacity: 0.7 }
            Label { textFormat: Text.PlainText; text: panel.units.formatDuration(panel.doc.analyzer.flightTimeSeconds) }
            Label { textFormat: Text.PlainText; text: qsTr("Waypoints"); opacity: 0.7 }
            Label { textFormat: Text.PlainText; text: panel.doc.analyzer.waypointCount }
            Label { textFormat: Text.PlainText; text: qsTr("Photos"); opacity: 0.7 }
            Label { textFormat: Text.PlainText; text: panel.doc.analyzer.photoCount }
        }

        ColumnLayout {
            // When, after the start, the route meets another vehicle's (the issue list says where).
            objectName: "conflictTimeline"
            visible: panel.deconfliction !== null && panel.deconfliction.count > 0
            Layout.fillWidth: true
            spacing: 0
            Label { textFormat: Text.PlainText; text: qsTr("Conflicts with other vehicles"); font.bold: true; color: panel.theme.problemText }
            Repeater {
                model: panel.deconfliction
                delegate: Label {
                    textFormat: Text.PlainText
                    required property var model  // RouteDeconfliction's roles
                    objectName: "conflictRow"
                    Layout.fillWidth: true
                    elide: Text.ElideRight
                    text: qsTr("%1:%2  leg %3 · %4 (%5): %6 m across, %7 m in height")
                          .arg(Math.floor(model.time / 60)).arg(String(Math.round(model.time % 60)).padStart(2, "0"))
                          .arg(model.leg).arg(model.otherVehicle)
                          .arg(model.flying ? qsTr("flying") : qsTr("uploaded"))
                          .arg(Math.round(model.horizontal)).arg(Math.round(model.vertical))
                    ToolTip.visible: conflictHover.hovered; ToolTip.text: model.text
                    HoverHandler { id: conflictHover }
                }
            }
        }

        GridLayout {
            // Will the battery last: the open route priced with the vehicle's energy profile. Two
            // rows, so the waypoint table keeps its room.
            objectName: "endurance"
            columns: 4
            columnSpacing: 8
            Layout.fillWidth: true
            readonly property RouteEndurance e: panel.endurance
            Label { textFormat: Text.PlainText; text: qsTr("Energy"); opacity: 0.7; visible: !parent.e.missing }
            RowLayout {
                visible: !parent.e.missing
                Label { textFormat: Text.PlainText; objectName: "enduranceEnergy"; text: parent.parent.e.missing ? "" : qsTr("%1 Wh").arg(Number(parent.parent.e.energyWh).toFixed(0)) }
                Label { textFormat: Text.PlainText; objectName: "enduranceAtEnd"
                        color: parent.parent.e.batteriesNeeded > 1 ? panel.theme.problemText : palette.windowText
                        text: parent.parent.e.missing ? "" : parent.parent.e.batteriesNeeded > 1
                              ? qsTr("%n batteries", "", parent.parent.e.batteriesNeeded)
                              : qsTr("%1 % left").arg(Math.round(parent.parent.e.batteryAtEnd * 100)) }
            }
            Label { textFormat: Text.PlainText; text: qsTr("No return"); opacity: 0.7; visible: !parent.e.missing }
            Label { textFormat: Text.PlainText; objectName: "enduranceNoReturn"; visible: !parent.e.missing; Layout.fillWidth: true; elide: Text.ElideRight
                    text: parent.e.missing ? "" : !parent.e.homeKnown ? qsTr("unknown: no home")
                          : parent.e.noReturnDistance !== undefined ? qsTr("after %1 (leg %2)").arg(panel.units.formatDistance(parent.e.noReturnDistance)).arg(parent.e.noReturnLeg)
                          : qsTr("none: home in reach")
                    ToolTip.visible: noReturnHover.hovered; ToolTip.text: qsTr("Beyond this point of the route, flying straight home no longer lands with the reserve")
                    HoverHandler { id: noReturnHover } }
            Label { textFormat: Text.PlainText; objectName: "enduranceProblem"; visible: parent.e.missing; Layout.columnSpan: 4; Layout.fillWidth: true
                    elide: Text.ElideRight; opacity: 0.8
                    text: parent.e.problem.length > 0 ? parent.e.problem : qsTr("Load an energy profile to see whether the battery lasts.")
                    ToolTip.visible: problemHover.hovered && truncated; ToolTip.text: text
                    HoverHandler { id: problemHover } }
            Label { textFormat: Text.PlainText; text: qsTr("Profile"); opacity: 0.7 }
            RowLayout {
                Layout.columnSpan: 3
                Layout.fillWidth: true
                spacing: 4
                Label { textFormat: Text.PlainText; objectName: "enduranceProfile"; Layout.fillWidth: true; elide: Text.ElideMiddle
                        text: parent.parent.e.profileName.length > 0 || parent.parent.e.profileSource.length > 0
                              ? qsTr("%1 (%2)").arg(parent.parent.e.profileName.length > 0 ? parent.parent.e.profileName : qsTr("unnamed")).arg(parent.parent.e.profileSource)
                              : qsTr("none") }
                Button { objectName: "energyProfileButton"; text: qsTr("Load…"); onClicked: profileDialog.open()
                         ToolTip.visible: hovered; ToolTip.text: qsTr("The vehicle's energy profile: a JSON file, e.g. from sortie-log fit") }
                Label { textFormat: Text.PlainText; text: qsTr("Wind"); opacity: 0.7; leftPadding: 4 }
                NumberField { theme: panel.theme; objectName: "windSpeedField"; Layout.preferredWidth: 44; units: panel.units; from: 0; to: 60
                              value: parent.parent.e.windSpeed
                              onNumberEntered: typed => parent.parent.e.windSpeed = typed
                              hint: qsTr("Wind speed, m/s") }
                Label { textFormat: Text.PlainText; text: qsTr("m/s from") }
                NumberField { theme: panel.theme; objectName: "windFromField"; Layout.preferredWidth: 44; units: panel.units; from: 0; to: 360
                              value: parent.parent.e.windFrom
                              onNumberEntered: typed => parent.parent.e.windFrom = typed
                              hint: qsTr("The direction the wind blows from, degrees clockwise from north") }
                Label { textFormat: Text.PlainText; text: "°" }
            }
        }

        // The chosen segment's and waypoints' editors share the height with the table: at their full
        // height while there is room, scrolled when the window is short, so the table keeps its rows.
        ScrollView {
            id: editors
            objectName: "segmentEditors"
            Layout.fillWidth: true
            Layout.fillHeight: true
            Layout.preferredHeight: editorColumn.implicitHeight
            Layout.maximumHeight: editorColumn.implicitHeight
            Layout.minimumHeight: Math.min(editorColumn.implicitHeight, 120)
            visible: editorColumn.implicitHeight > 0
            contentWidth: availableWidth
            clip: true
            ColumnLayout {
                id: editorColumn
                width: editors.availableWidth
                spacing: 4
                SegmentEditor {
                    theme: panel.theme
                    Layout.fillWidth: true
                    units: panel.units
                    editor: panel.doc.segmentEditor
                }
                ActionEditor {
                    theme: panel.theme
                    objectName: "actionEditor"
                    Layout.fillWidth: true
                    actions: panel.doc.actionEditor
                }
            }
        }

        // When the flight is planned to start, in the operator's time zone: geographical zones count
        // when their schedule meets the flight (empty: it starts now). Parsed and kept by the editor.
        RowLayout {
            Layout.fillWidth: true
            spacing: 4
            Label { textFormat: Text.PlainText; text: qsTr("Planned start") }
            TextField {
                objectName: "plannedStartField"
                Layout.fillWidth: true
                text: panel.doc.model.plannedStartText
                placeholderText: qsTr("now (or e.g. %1)").arg("2026-06-06 18:00") // i18n: not text (a date in the field's format)
                selectByMouse: true
                onEditingFinished: if (text !== panel.doc.model.plannedStartText && !panel.doc.editor.setPlannedStartText(text))
                                       text = Qt.binding(() => panel.doc.model.plannedStartText)
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Year-month-day hours:minutes, your time zone; empty: the flight starts now")
            }
        }

        ListView {
            objectName: "validationList"
            visible: count > 0
            Layout.fillWidth: true
            Layout.preferredHeight: Math.min(contentHeight, 90)
            clip: true
            model: panel.doc.analyzer.issues
            delegate: ItemDelegate {
                id: issue
                required property string severity
                required property string message
                required property int segment
                width: ListView.view.width
                text: message
                // A coloured mark, not an emoji: the fonts an operator has may not carry one.
                contentItem: RowLayout {
                    spacing: 6
                    Rectangle {
                        implicitWidth: 10; implicitHeight: 10; radius: 5
                        color: issue.severity === "error" ? panel.theme.problem : panel.theme.warning
                    }
                    Label { textFormat: Text.PlainText; text: issue.message; wrapMode: Text.Wrap; Layout.fillWidth: true }
                }
                onClicked: {
                    if (segment >= 0)
                        panel.doc.selectRows([segment])
                    if (panel.airspace)
                        panel.airspace.selectZoneOfIssue(message)
                }
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Select the segment")
            }
        }

        ListView {
            objectName: "serverMessages"
            visible: count > 0
            Layout.fillWidth: true
            Layout.preferredHeight: Math.min(contentHeight, 70)
            clip: true
            model: panel.preparation.notices
            delegate: Label { textFormat: Text.PlainText; required property string modelData; text: modelData; wrapMode: Text.Wrap; width: ListView.view.width }
        }

        WaypointTable {
            theme: panel.theme
            id: waypointTable
            units: panel.units
            Layout.fillWidth: true
            Layout.fillHeight: true
            Layout.minimumHeight: 140  // a header and four rows, whatever the editors above take
            Layout.preferredHeight: 1000
            doc: panel.doc
            routeModel: panel.routeModel
            terrain: panel.terrain
        }
    }
}
