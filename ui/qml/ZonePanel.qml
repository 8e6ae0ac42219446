import QtQuick
import QtQuick.Controls
import QtQuick.Dialogs
import QtQuick.Layouts
import Sortie.Ui

// The zones over the map (core/airspace/client's Airspace): load zone files, draw zones, switch
// zones off, choose one (the map highlights it), and edit the chosen drawn zone's name, kind, floor
// and ceiling. Every edit is the zone editor's (one undo step each); the rules are in C++.
Frame {
    id: panel
    required property Theme theme
    required property Airspace airspace
    required property ZoneSharing sharing  // send a drawn zone; edit or delete a server custom zone
    required property RouteEditor routeEditor  // an authorisation for a geographical zone is the route's
    required property ZoneFeed feed            // a published zone file fetched from its URL and kept
    required property string tool          // the page's drawing tool ("zonePolygon", "zoneCircle" or another)
    required property int draftCount       // corners clicked so far while drawing a polygon
    signal toolRequested(string tool)      // "" ends drawing
    signal finishRequested()               // make the polygon drawn so far a zone
    readonly property ZoneEditor editor: airspace.editor
    readonly property int chosen: airspace.selectedCustom
    readonly property geoZoneDetails geoZone: airspace.selectedGeoZone
    padding: 8

    FileDialog {
        id: zoneDialog
        title: qsTr("Load zones")
        nameFilters: [qsTr("Zones (*.geojson *.json *.kml *.plan)"), qsTr("All files (*)")]
        onAccepted: panel.airspace.loadFileUrl(selectedFile)
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 4
        RowLayout {
            Layout.fillWidth: true
            Label { textFormat: Text.PlainText; text: qsTr("Zones (%1)").arg(panel.airspace.count); font.bold: true; Layout.fillWidth: true }
            ToolButton { objectName: "zoneUndo"; text: qsTr("Undo"); enabled: panel.editor.canUndo; onClicked: panel.editor.undo() }
            ToolButton { objectName: "zoneRedo"; text: qsTr("Redo"); enabled: panel.editor.canRedo; onClicked: panel.editor.redo() }
        }
        // A published zone file (a country's ED-269 or ED-318 feed) from its web address; kept for
        // flying offline and fetched again with Refresh.
        RowLayout {
            Layout.fillWidth: true
            TextField {
                id: feedUrl
                objectName: "zoneFeedUrl"
                Layout.fillWidth: true
                placeholderText: qsTr("Zone feed URL (https://…)")
                selectByMouse: true
                onAccepted: fetchButton.clicked()
            }
            Button {
                id: fetchButton
                objectName: "fetchZoneFeedButton"
                text: panel.feed.busy ? qsTr("Fetching…") : qsTr("Fetch")
                enabled: !panel.feed.busy && feedUrl.text.length > 0
                onClicked: panel.feed.fetch(feedUrl.text)
            }
            Button {
                objectName: "refreshZoneFeedsButton"
                text: qsTr("Refresh")
                visible: panel.airspace.feedUrls.length > 0
                enabled: !panel.feed.busy
                onClicked: panel.feed.fetch(panel.airspace.feedUrls[0])
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Fetch the zone feed again from %1").arg(panel.airspace.feedUrls.length > 0 ? panel.airspace.feedUrls[0].toString() : "")
            }
        }
        Label {
            textFormat: Text.PlainText
            objectName: "zoneFeedProblem"
            visible: text.length > 0
            text: panel.feed.problem
            color: panel.theme.problemText
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
        Label {
            textFormat: Text.PlainText
            objectName: "zoneDataAge"
            visible: text.length > 0
            text: panel.airspace.dataAge
            color: panel.airspace.dataStale ? panel.theme.warningText : palette.placeholderText
            font.pixelSize: panel.theme.smallFontSize
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
        RowLayout {
            Layout.fillWidth: true
            Button { objectName: "loadZonesButton"; text: qsTr("Load…"); onClicked: zoneDialog.open() }
            Button {
                objectName: "drawZonePolygon"
                text: qsTr("Polygon")
                checkable: true
                checked: panel.tool === "zonePolygon"
                onToggled: panel.toolRequested(checked ? "zonePolygon" : "")
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Click the corners on the map, then Create")
            }
            Button {
                objectName: "drawZoneCircle"
                text: qsTr("Circle")
                checkable: true
                checked: panel.tool === "zoneCircle"
                onToggled: panel.toolRequested(checked ? "zoneCircle" : "")
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Click the centre on the map; drag its handle for the radius")
            }
        }
        RowLayout {
            visible: panel.tool === "zonePolygon"
            Layout.fillWidth: true
            Label { textFormat: Text.PlainText; text: qsTr("%1 corners").arg(panel.draftCount); Layout.fillWidth: true }
            Button { objectName: "finishZoneButton"; text: qsTr("Create"); enabled: panel.draftCount >= 3; onClicked: panel.finishRequested() }
        }
        Label {
            textFormat: Text.PlainText
            id: refusal
            objectName: "zoneRefusal"
            visible: text.length > 0
            color: panel.theme.problemText
            wrapMode: Text.Wrap
            Layout.fillWidth: true
            Connections {
                target: panel.editor
                function onRefused(reason) { refusal.text = reason }
                function onStackChanged() { refusal.text = "" }
            }
        }
        Label {
            textFormat: Text.PlainText
            objectName: "zoneProblems"
            visible: panel.airspace.problems.length > 0
            text: panel.airspace.problems.join("\n")
            color: panel.theme.problemText
            wrapMode: Text.Wrap
            Layout.fillWidth: true
            Layout.maximumHeight: 80
            elide: Text.ElideRight
        }
        ListView {
            id: zoneList
            objectName: "zoneList"
            Layout.fillWidth: true
            Layout.preferredHeight: Math.min(contentHeight, 160)
            clip: true
            model: panel.airspace.zones
            delegate: ItemDelegate {
                id: row
                required property int index
                required property string name
                required property string kind
                required property string source
                required property string floor
                required property string ceiling
                required property bool active
                required property bool selected
                required property string problem
                required property var model
                width: ListView.view.width
                highlighted: selected
                onClicked: panel.airspace.selectedZone = index
                contentItem: RowLayout {
                    spacing: 4
                    CheckBox {
                        objectName: "zoneActive"
                        checked: row.active
                        onToggled: row.model.active = checked
                        ToolTip.visible: hovered
                        ToolTip.text: qsTr("Checked against the route when ticked")
                    }
                    Rectangle {
                        implicitWidth: 10; implicitHeight: 10
                        color: row.kind === "exclusion" ? panel.theme.mapExclusion : "transparent"
                        border.color: row.kind === "exclusion" ? panel.theme.mapExclusion : panel.theme.mapInclusion
                        border.width: 2
                    }
                    ColumnLayout {
                        spacing: 0
                        Layout.fillWidth: true
                        Label { textFormat: Text.PlainText; text: row.name; font.bold: true; elide: Text.ElideRight; Layout.fillWidth: true }
                        Label {
                            textFormat: Text.PlainText
                            text: row.problem.length > 0 ? row.problem : qsTr("%1 · %2 – %3").arg(row.source).arg(row.floor).arg(row.ceiling)
                            color: row.problem.length > 0 ? panel.theme.problemText : palette.placeholderText
                            font.pixelSize: 11
                            elide: Text.ElideRight
                            Layout.fillWidth: true
                        }
                    }
                }
            }
        }
        // The chosen geographical zone (ED-269, ED-318): what it restricts, when, who to ask; the
        // route's authorisation for it, recorded here (one undo step of the route).
        ColumnLayout {
            objectName: "geoZoneDetails"
            visible: panel.geoZone.valid
            Layout.fillWidth: true
            spacing: 2
            Label {
                textFormat: Text.PlainText
                objectName: "geoZoneRestriction"
                text: qsTr("%1 · %2").arg(panel.geoZone.restriction).arg(panel.geoZone.identifier)
                font.bold: true
                wrapMode: Text.Wrap
                Layout.fillWidth: true
            }
            Label {
                textFormat: Text.PlainText
                objectName: "geoZoneText"
                text: panel.geoZone.text
                wrapMode: Text.Wrap
                font.pixelSize: panel.theme.smallFontSize
                Layout.fillWidth: true
            }
            RowLayout {
                visible: panel.geoZone.needsAuthorisation
                Layout.fillWidth: true
                TextField {
                    id: authorisationField
                    objectName: "authorisationField"
                    Layout.fillWidth: true
                    placeholderText: qsTr("Authorisation reference")
                    text: panel.geoZone.authorisation
                    selectByMouse: true
                }
                Button {
                    objectName: "recordAuthorisationButton"
                    text: panel.geoZone.authorisation.length > 0 ? qsTr("Change") : qsTr("Record")
                    enabled: authorisationField.text !== panel.geoZone.authorisation
                    onClicked: panel.routeEditor.recordAuthorisation(panel.geoZone.identifier, authorisationField.text)
                    ToolTip.visible: hovered
                    ToolTip.text: qsTr("Kept with the route; the check then warns instead of refusing (empty: removed)")
                }
            }
        }
        // The chosen drawn zone's fields.
        GridLayout {
            objectName: "zoneFields"
            visible: panel.chosen >= 0
            columns: 2
            Layout.fillWidth: true
            Label { textFormat: Text.PlainText; text: qsTr("Name") }
            TextField {
                objectName: "zoneName"
                Layout.fillWidth: true
                text: panel.editor.fields.name
                onEditingFinished: if (text !== panel.editor.fields.name) panel.editor.setName(panel.chosen, text)
            }
            Label { textFormat: Text.PlainText; text: qsTr("Kind") }
            ComboBox {
                objectName: "zoneKind"
                Layout.fillWidth: true
                textRole: "text"
                valueRole: "value"
                model: [{value: "exclusion", text: qsTr("exclusion")}, {value: "inclusion", text: qsTr("inclusion")}]
                currentIndex: panel.editor.fields.inclusion ? 1 : 0
                onActivated: index => panel.editor.setKind(panel.chosen, model[index].value)
            }
            Label { textFormat: Text.PlainText; text: qsTr("Floor (m)") }
            TextField {
                id: floorField
                objectName: "zoneFloor"
                Layout.fillWidth: true
                placeholderText: qsTr("ground")
                text: panel.editor.fields.floor
                onEditingFinished: panel.setLimits()
            }
            Label { textFormat: Text.PlainText; text: qsTr("Ceiling (m)") }
            TextField {
                id: ceilingField
                objectName: "zoneCeiling"
                Layout.fillWidth: true
                placeholderText: qsTr("unlimited")
                text: panel.editor.fields.ceiling
                onEditingFinished: panel.setLimits()
            }
            Label { textFormat: Text.PlainText; text: qsTr("Above") }
            ComboBox {
                id: referenceBox
                objectName: "zoneReference"
                Layout.fillWidth: true
                textRole: "text"
                valueRole: "value"
                // AMSL and AGL are aviation abbreviations, the same in every language; "above home" is not
                model: [{value: "AMSL", text: "AMSL"}, {value: "AGL", text: "AGL"}, {value: "HOME", text: qsTr("HOME")}] // i18n: not text (AMSL, AGL)
                currentIndex: Math.max(0, indexOfValue(panel.editor.fields.reference))
                onActivated: panel.setLimits()
            }
            RowLayout {
                Layout.columnSpan: 2
                Layout.fillWidth: true
                Button {
                    objectName: "removeZoneButton"
                    text: panel.sharing.sendUpdates ? qsTr("Discard copy") : qsTr("Remove zone")
                    onClicked: panel.editor.removeZone(panel.chosen)
                    ToolTip.visible: hovered && panel.sharing.sendUpdates
                    ToolTip.text: qsTr("The server's zone stays as it is")
                }
                Button {
                    objectName: "sendZoneButton"
                    text: panel.sharing.sendUpdates ? qsTr("Update on server") : qsTr("Send to server")
                    enabled: !panel.sharing.busy
                    onClicked: panel.sharing.send(panel.chosen)
                }
            }
        }
        // The chosen zone is one of the server's custom zones: edit a copy here, or delete it.
        RowLayout {
            objectName: "serverZoneActions"
            visible: panel.sharing.canEditOnServer
            Layout.fillWidth: true
            Button {
                objectName: "editServerZone"
                text: qsTr("Edit here")
                onClicked: panel.sharing.editCopy(panel.airspace.selectedZone)
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Draw a copy to edit; Update on server stores it")
            }
            Button {
                objectName: "deleteServerZone"
                text: qsTr("Delete on server")
                enabled: !panel.sharing.busy
                onClicked: deleteQuestion.open()
            }
        }
        Label {
            textFormat: Text.PlainText
            objectName: "zoneSharingStatus"
            visible: text.length > 0
            text: panel.sharing.busy ? qsTr("Waiting for the server…") : panel.sharing.status
            color: panel.sharing.failed ? panel.theme.problemText : palette.text
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
        RowLayout {
            Layout.fillWidth: true
            Label { textFormat: Text.PlainText; text: qsTr("Warn within (m)"); Layout.fillWidth: true }
            SpinBox {
                objectName: "zoneBuffer"
                from: 0
                to: 5000
                stepSize: 5
                editable: true
                value: Math.round(panel.airspace.buffer)
                onValueModified: panel.airspace.buffer = value
            }
        }
    }

    Dialog {
        id: deleteQuestion
        objectName: "deleteZoneQuestion"
        parent: Overlay.overlay
        anchors.centerIn: parent
        modal: true
        title: qsTr("Delete zone")
        standardButtons: Dialog.Yes | Dialog.No
        // Which zone is read when asked: the selection may change while the question is open.
        property int row: -1
        onAboutToShow: row = panel.airspace.selectedZone
        width: 380
        Label {
            textFormat: Text.PlainText
            width: deleteQuestion.availableWidth
            wrapMode: Text.Wrap
            text: qsTr("Delete '%1' on the server, for every operator?").arg(panel.airspace.zoneName(deleteQuestion.row))
        }
        onAccepted: panel.sharing.removeFromServer(row)
    }

    // As typed: the editor reads the numbers, takes empty as ground / unlimited and refuses the rest.
    function setLimits() {
        panel.editor.setLimits(panel.chosen, floorField.text, ceilingField.text, referenceBox.currentValue)
    }
}
