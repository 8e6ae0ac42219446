import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The actions at the selected waypoints (WaypointActionsModel): each with its fields, a kind to
// add, remove one. Every change is a call on the model, which checks it and makes it one undo step.
GroupBox {
    id: box
    required property Theme theme
    required property WaypointActionsModel actions
    visible: actions.valid
    title: actions.title
    // What a field row shows while the Repeater's count runs ahead of the list (no field, no value).
    property actionFieldRow noField

    // A layout places new items when the next frame is drawn; until then a freshly added action's
    // fields all stand at the editor's corner, on top of one another, and a click there lands in its
    // last field (tst_uiflows actionsAtAWaypoint, 3 runs in 10 on an idle machine). LayOutOnAdd lays
    // the editor out as rows appear, so every field is where it is drawn from the moment it exists.
    ColumnLayout {
        id: column
        anchors.fill: parent
        spacing: 4

        Label {
            textFormat: Text.PlainText
            visible: box.actions.mixed
            text: qsTr("The selected waypoints have different actions: these are the first one's. An edit applies where they match; an added action goes to all.")
            wrapMode: Text.Wrap
            opacity: 0.8
            Layout.fillWidth: true
        }

        Repeater {
            model: box.actions
            LayOutOnAdd.layout: column
            delegate: Frame {
                id: action
                required property int index
                required property string summary
                required property var fields
                required property bool editable
                objectName: "action_" + index
                Layout.fillWidth: true
                padding: 6

                ColumnLayout {
                    anchors.fill: parent
                    spacing: 2
                    RowLayout {
                        Layout.fillWidth: true
                        Label {
                            textFormat: Text.PlainText
                            id: summaryLabel
                            text: action.summary
                            font.bold: true
                            elide: Text.ElideRight
                            Layout.fillWidth: true
                            // The whole summary where the panel is too narrow for it.
                            HoverHandler { id: summaryHover }
                            ToolTip.visible: summaryLabel.truncated && summaryHover.hovered
                            ToolTip.text: action.summary
                        }
                        Button {
                            objectName: "removeAction_" + action.index
                            text: qsTr("Remove")
                            flat: true
                            onClicked: box.actions.remove(action.index)
                        }
                    }
                    Label {
                        textFormat: Text.PlainText
                        visible: !action.editable
                        text: qsTr("Sent by the server; kept and sent back unchanged.")
                        opacity: 0.7
                        wrapMode: Text.Wrap
                        Layout.fillWidth: true
                    }
                    // By count, not by list: an edited value then updates its row in place
                    // instead of rebuilding every field (and losing the focus being typed in).
                    Repeater {
                        model: action.fields.length
                        LayOutOnAdd.layout: column
                        delegate: RowLayout {
                            id: field
                            required property int index
                            // An ActionFieldRow: what the field is and its value, typed in C++.
                            readonly property actionFieldRow row: action.fields[index] ?? box.noField
                            spacing: 6
                            Label {
                                textFormat: Text.PlainText
                                text: field.row.label
                                elide: Text.ElideRight
                                Layout.preferredWidth: 150
                            }
                            TextField {
                                objectName: "action_" + field.row.action + "_" + field.row.name
                                visible: field.row.number
                                text: field.row.text
                                selectByMouse: true
                                Layout.preferredWidth: 110
                                onEditingFinished: if (text !== field.row.text) box.actions.setField(field.row.action, field.row.name, text)
                            }
                            Switch {
                                objectName: "action_" + field.row.action + "_" + field.row.name + "_switch"
                                visible: field.row.toggle
                                checked: field.row.on
                                onToggled: box.actions.setField(field.row.action, field.row.name, checked)
                            }
                            ComboBox {
                                objectName: "action_" + field.row.action + "_" + field.row.name + "_choice"
                                visible: field.row.choice
                                model: field.row.choiceTexts
                                currentIndex: field.row.choiceIndex
                                Layout.preferredWidth: 190
                                onActivated: index => box.actions.setField(field.row.action, field.row.name, field.row.choiceValues[index])
                            }
                            Label { textFormat: Text.PlainText; text: field.row.unit; opacity: 0.7 }
                        }
                    }
                }
            }
        }

        RowLayout {
            Layout.fillWidth: true
            ComboBox {
                id: kindPicker
                objectName: "actionKindPicker"
                model: box.actions.kindLabels
                Layout.preferredWidth: 190
            }
            Button {
                objectName: "addActionButton"
                text: qsTr("Add action")
                enabled: kindPicker.currentIndex >= 0
                onClicked: box.actions.addKindAt(kindPicker.currentIndex)
            }
            Button {
                objectName: "clearActionsButton"
                text: qsTr("Remove all")
                visible: box.actions.count > 0
                onClicked: box.actions.clear()
            }
        }

        Label {
            textFormat: Text.PlainText
            objectName: "actionProblem"
            visible: text.length > 0
            text: box.actions ? box.actions.problem : ""
            color: box.theme.problemText
            wrapMode: Text.Wrap
            Layout.fillWidth: true
        }
    }
}
