import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The current segment's editor, generated from its algorithm's description (SegmentEditorModel:
// the server's TraverseAlgorithm definitions, the built-in ones offline). One field per parameter,
// drawn by its widget hint; every change is editor.set(), which validates and undoes. Sortie's own
// knowledge adds the angle dial, the camera picker and the live survey figures.
GroupBox {
    id: box
    required property Theme theme
    required property SegmentEditorModel editor
    required property DisplayUnits units // numbers as the operator's language writes them
    property bool showAdvanced: false
    visible: editor.valid
    title: editor.title

    ColumnLayout {
        anchors.fill: parent
        spacing: 2

        RowLayout {
            visible: !isNaN(box.editor.radius)
            Label { textFormat: Text.PlainText; text: qsTr("Radius"); Layout.preferredWidth: 150 }
            NumberField {
                theme: box.theme
                objectName: "segment_radius"
                units: box.units
                from: 0
                value: box.editor.radius
                decimals: 1
                Layout.preferredWidth: 80
                onNumberEntered: typed => { if (Math.abs(typed - box.editor.radius) >= 0.05) box.editor.setRadius(typed) }
            }
            Label { textFormat: Text.PlainText; text: qsTr("m"); opacity: 0.7 }
        }

        Repeater {
            model: box.editor
            delegate: RowLayout {
                id: field
                required property int index
                required property string name
                required property string label
                required property string description
                required property string widget
                required property string unit
                required property var value
                required property string valueText
                required property string defaultValue
                required property string defaultText
                required property var choices
                required property bool advanced
                required property bool known
                required property string problem
                visible: box.showAdvanced || !advanced
                Layout.fillWidth: true
                ToolTip.visible: hover.hovered && description.length > 0
                ToolTip.text: description
                HoverHandler { id: hover }

                Label {
                    textFormat: Text.PlainText
                    text: field.known ? field.label : field.label + " ⋯"
                    color: field.problem.length > 0 ? box.theme.problemText : palette.windowText
                    elide: Text.ElideRight
                    Layout.preferredWidth: 150
                }
                TextField {
                    objectName: "segment_" + field.name
                    visible: field.widget === "number" || field.widget === "text"
                    text: field.valueText
                    placeholderText: field.defaultText
                    selectByMouse: true
                    Layout.preferredWidth: 110
                    onEditingFinished: if (text !== field.valueText) box.editor.set(field.index, text)
                }
                Switch {
                    objectName: "segment_" + field.name + "_switch"
                    visible: field.widget === "toggle"
                    checked: field.value === true || (field.value === undefined && field.defaultValue === "true")
                    onToggled: box.editor.set(field.index, checked)
                }
                ComboBox {
                    objectName: "segment_" + field.name + "_choice"
                    visible: field.widget === "choice" || field.widget === "camera"
                    Layout.preferredWidth: 180
                    model: field.choices
                    textRole: "text"
                    valueRole: "value"
                    currentIndex: visible ? indexOfValue(field.value === undefined ? field.defaultValue : field.value) : -1
                    displayText: currentIndex < 0 && field.value !== undefined ? String(field.value) : currentText
                    onActivated: box.editor.set(field.index, currentValue)
                }
                Dial {
                    // The direction of passes: drag it round; the path follows, one undo step.
                    objectName: "segment_" + field.name + "_dial"
                    visible: field.widget === "angle"
                    from: 0
                    to: 360
                    value: field.widget === "angle" && field.value !== undefined ? Number(field.value) : 0
                    implicitWidth: 44
                    implicitHeight: 44
                    onMoved: box.editor.set(field.index, Math.round(value), MissionEnums.Continuing)
                    onPressedChanged: if (!pressed) box.editor.set(field.index, Math.round(value), MissionEnums.Done)
                }
                TextField {
                    visible: field.widget === "angle"
                    text: field.valueText
                    Layout.preferredWidth: 60
                    selectByMouse: true
                    onEditingFinished: box.editor.set(field.index, text)
                }
                Label { textFormat: Text.PlainText; text: field.unit; opacity: 0.7 }
            }
        }

        CheckBox {
            objectName: "segment_showAdvanced"
            text: qsTr("Advanced parameters")
            checked: box.showAdvanced
            onToggled: box.showAdvanced = checked
        }

        Label {
            textFormat: Text.PlainText
            // What the survey gives, as the operator types.
            objectName: "segment_figures"
            visible: text.length > 0
            text: box.editor.figuresText
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
        Label {
            textFormat: Text.PlainText
            objectName: "segment_problem"
            visible: text.length > 0
            text: box.editor.problem
            color: box.theme.problemText
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
    }
}
