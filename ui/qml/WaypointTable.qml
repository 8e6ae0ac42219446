import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The route as a table beside the map: one row per segment, cells edited in place, a click
// selects (Ctrl toggles, Shift extends), and the bar above edits every selected row at once.
// Every edit is one call of the document's RouteEditor (one undo step).
ColumnLayout {
    id: table
    required property Theme theme
    required property RouteDocument doc
    required property AbstractItemModel routeModel
    required property TerrainProfileModel terrain  // ground and converted heights per row
    required property DisplayUnits units            // numbers as the operator's language writes them
    readonly property list<int> selected: doc.selectedRows
    // Which height the altitude column shows: as each row sets it, or all AMSL, or all AGL.
    readonly property int heightsShown: heightsPicker.currentIndex
    readonly property int heightsFrame: heightsShown === 1 ? MissionEnums.Amsl : MissionEnums.Agl
    spacing: 4

    // A cell: coordinates always with a dot (as DisplayUnits shows them), other numbers in the
    // language's format; what is typed is read either way, and text that is no number is refused.
    component Cell: NumberField {
        theme: table.theme
        property string role
        property var rowModel               // the delegate's row: its roles as a JS object
        signal edited(real value)
        value: rowModel[role]               // undefined: nothing to show or edit
        plainDot: role === "latitude" || role === "longitude"
        decimals: plainDot ? 6 : 1
        units: table.units
        readOnly: !table.doc || value === undefined
        padding: 2
        onNumberEntered: typed => { if (Math.abs(typed - Number(value)) >= 1e-7) edited(typed) }
    }

    // A Flow, not a row: in a longer language the fields go on to a second line rather than past the panel.
    Flow {
        Layout.fillWidth: true
        spacing: 5
        Label { textFormat: Text.PlainText; text: qsTr("%n selected:", "", table.selected.length); height: bulkAltitude.height; verticalAlignment: Text.AlignVCenter }
        NumberField { theme: table.theme; id: bulkAltitude; objectName: "bulkAltitude"; units: table.units; allowEmpty: true; placeholderText: qsTr("alt m"); width: 60 }
        Button {
            objectName: "bulkAltitudeButton"
            text: qsTr("Set")
            enabled: table.selected.length > 0 && bulkAltitude.number !== undefined
            onClicked: table.doc.editor.setAltitude(table.selected, bulkAltitude.number)
        }
        NumberField { theme: table.theme; id: bulkSpeed; objectName: "bulkSpeed"; units: table.units; allowEmpty: true; from: 0; placeholderText: qsTr("m/s"); width: 50 }
        Button {
            objectName: "bulkSpeedButton"
            text: qsTr("Set")
            enabled: table.selected.length > 0 && bulkSpeed.number !== undefined
            onClicked: table.doc.editor.setSpeed(table.selected, bulkSpeed.number)
        }
        ComboBox {
            model: ["AGL", "AMSL"] // i18n: not text (aviation abbreviations, the same in every language)
            enabled: table.selected.length > 0
            width: 76
            onActivated: table.doc.editor.setAltitudeType(table.selected, currentIndex === 0 ? MissionEnums.Agl : MissionEnums.Amsl)
            ToolTip.visible: hovered
            ToolTip.text: qsTr("Altitude above ground (AGL) or above mean sea level (AMSL)")
        }
    }

    RowLayout {
        Layout.fillWidth: true
        Label { textFormat: Text.PlainText; text: qsTr("Heights:") }
        ComboBox {
            id: heightsPicker
            objectName: "heightsShown"
            model: [qsTr("as set"), qsTr("all AMSL"), qsTr("all AGL")]
            Layout.preferredWidth: 110
            ToolTip.visible: hovered
            ToolTip.text: qsTr("AMSL and AGL are converted through the ground under each waypoint")
        }
        Label {
            textFormat: Text.PlainText
            text: qsTr("ground: %1").arg(table.terrain.sourceText)
            elide: Text.ElideRight
            opacity: 0.7
            Layout.fillWidth: true
        }
    }

    // One width per column, for the header and the rows alike: the cells' width, or the header's
    // words if they are wider (German "Geschw.", Spanish "Velocidad"); the last column takes the
    // rest, never less than its header. The panel beside the map asks for neededWidth.
    readonly property list<string> headers: [
        qsTr("#"), qsTr("Latitude"), qsTr("Longitude"),
        heightsShown === 0 ? qsTr("Alt") : heightsShown === 1 ? qsTr("AMSL") : qsTr("AGL"),
        qsTr("Type"), qsTr("Ground"), qsTr("Speed"), qsTr("Actions")]
    readonly property var cellWidths: [28, 78, 78, 50, 42, 52, 48]
    readonly property int columnSpacing: 2
    function headerPadding(column) { return column > 0 && column < 4 || column === 6 ? 2 : 0 } // over the cells' text
    function headerWidth(column) { return Math.ceil(headerMetrics.advanceWidth(headers[column])) + headerPadding(column) + 4 } // and a gap before the next
    readonly property var columnWidths: cellWidths.map((w, column) => Math.max(w, headerWidth(column)))
    readonly property real neededWidth: columnWidths.reduce((sum, w) => sum + w, 0)
                                         + headerWidth(headers.length - 1) + columnSpacing * (headers.length - 1)
    Label { textFormat: Text.PlainText; id: headerProbe; visible: false; font.bold: true }
    FontMetrics { id: headerMetrics; font: headerProbe.font }
    RowLayout {
        Layout.fillWidth: true
        spacing: table.columnSpacing
        Repeater {
            model: table.headers.length  // a count: a new language or height frame rewords the labels, never remakes them
            Label {
                textFormat: Text.PlainText
                required property int index
                objectName: "waypointHeader_" + index
                text: table.headers[index]
                font.bold: true
                elide: Text.ElideRight
                Layout.preferredWidth: index < table.columnWidths.length ? table.columnWidths[index] : -1
                Layout.fillWidth: index >= table.columnWidths.length
                leftPadding: table.headerPadding(index)
            }
        }
    }

    ListView {
        id: list
        objectName: "waypointList"
        Layout.fillWidth: true
        Layout.fillHeight: true
        clip: true
        model: table.routeModel
        ScrollBar.vertical: ScrollBar {}
        delegate: Rectangle {
            id: row
            required property int index
            required property var model
            readonly property bool isSelected: table.selected.indexOf(index) >= 0
            width: ListView.view.width
            height: 28
            color: isSelected ? table.theme.rowSelected : index % 2 ? table.theme.rowStripe : "transparent"
            MouseArea {
                anchors.fill: parent
                onClicked: mouse => { if (table.doc) table.doc.clickRow(row.index, mouse.modifiers) }
            }
            RowLayout {
                anchors.fill: parent
                spacing: table.columnSpacing
                Label { textFormat: Text.PlainText; text: row.index + 1; Layout.preferredWidth: table.columnWidths[0]; horizontalAlignment: Text.AlignHCenter }
                Cell { role: "latitude"; rowModel: row.model; Layout.preferredWidth: table.columnWidths[1]
                       onEdited: value => table.doc.editor.setLatitude(row.index, value) }
                Cell { role: "longitude"; rowModel: row.model; Layout.preferredWidth: table.columnWidths[2]
                       onEdited: value => table.doc.editor.setLongitude(row.index, value) }
                Cell {
                    objectName: "altitudeCell_" + row.index
                    role: "altitude"
                    rowModel: row.model
                    // Converted heights follow the terrain profile (its revision makes the binding re-read).
                    value: table.heightsShown === 0 ? row.model.altitude
                         : (table.terrain.revision, table.terrain.altitudeOfRow(row.index, table.heightsFrame))
                    Layout.preferredWidth: table.columnWidths[3]
                    onEdited: typed => table.heightsShown === 0 ? table.doc.editor.setAltitude([row.index], typed)
                                                                 : table.doc.editor.setAltitudeIn([row.index], typed, table.heightsFrame)
                }
                Label { textFormat: Text.PlainText; text: row.model.altitudeType !== undefined ? row.model.altitudeType : ""; Layout.preferredWidth: table.columnWidths[4] }
                Label {
                    textFormat: Text.PlainText
                    id: ground
                    objectName: "groundCell_" + row.index
                    text: (table.terrain.revision, table.units.language, table.terrain.groundTextOfRow(row.index))
                    elide: Text.ElideRight
                    Layout.preferredWidth: table.columnWidths[5]
                    HoverHandler { id: groundHover }
                    ToolTip.visible: groundHover.hovered && text.length > 0
                    ToolTip.text: table.terrain.groundToolTipOfRow(row.index)
                }
                Cell { role: "speed"; rowModel: row.model; Layout.preferredWidth: table.columnWidths[6]
                       onEdited: value => table.doc.editor.setSpeed([row.index], value) }
                Label {
                    textFormat: Text.PlainText
                    text: row.model.kind === "areaScan" ? qsTr("Area scan") : row.model.actionsSummary !== undefined ? row.model.actionsSummary : ""
                    elide: Text.ElideRight
                    Layout.fillWidth: true
                }
            }
        }
    }
}
