import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The fly view's one banner for in-flight alerts: every row of every monitor given (each an
// AlertModel: the battery's advice, closest approaches, zones), a warning amber and a danger red,
// while there is one. A battery alert offers Return home; the page asks before it sends anything
// (the banner appears under the operator's pointer: a click meant for something else must not send
// the vehicle home).
ColumnLayout {
    id: banner
    required property Theme theme
    // The monitors, in the order their rows are shown; a null entry (no fleet yet) shows nothing.
    property list<AlertModel> monitors
    property bool hidden: false             // a replayed flight has no live alerts to show
    property bool canReturnHome: false      // a vehicle is chosen
    signal returnHomeRequested()
    readonly property int count: {
        let n = 0
        for (let i = 0; i < monitors.length; ++i)
            n += monitors[i] ? monitors[i].count : 0
        return n
    }
    visible: count > 0 && !hidden
    spacing: 0

    Repeater {
        model: banner.monitors
        delegate: Repeater {
            id: monitorRows
            required property AlertModel modelData
            model: modelData
            delegate: Rectangle {
                id: row
                required property var model   // AlertModel's roles
                readonly property int subject: monitorRows.modelData.subject
                Layout.fillWidth: true
                implicitHeight: rowLayout.implicitHeight + 8
                color: model.warning ? banner.theme.warning : banner.theme.problem
                RowLayout {
                    id: rowLayout
                    anchors.fill: parent
                    anchors.leftMargin: 6
                    anchors.rightMargin: 6
                    spacing: 8
                    Label {
                        textFormat: Text.PlainText
                        objectName: row.subject === AlertModel.Battery ? "enduranceAdvice"
                                  : row.subject === AlertModel.Airspace ? "zoneAlert" : "proximityAlert"
                        Layout.fillWidth: true
                        text: row.subject === AlertModel.Proximity ? qsTr("Too close: %1").arg(row.model.text)
                            : row.subject === AlertModel.Airspace ? qsTr("Airspace: %1").arg(row.model.text)
                            : row.model.text
                        color: row.model.warning ? banner.theme.onWarning : banner.theme.onProblem
                        font.bold: true
                        wrapMode: Text.Wrap
                    }
                    Button {
                        objectName: "adviceReturnHomeButton"
                        visible: row.subject === AlertModel.Battery
                        text: qsTr("Return home")
                        enabled: banner.canReturnHome
                        onClicked: banner.returnHomeRequested()
                    }
                }
            }
        }
    }
}
