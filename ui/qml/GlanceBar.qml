import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// The toolbar's glance: the connection, the vehicle, its GPS, battery and link, each an icon and a
// few words in its level's colour (ok, warning, problem, missing). GlanceStatus judges and words
// them; this view only lays them out.
RowLayout {
    id: bar
    required property GlanceStatus status
    required property Theme theme
    spacing: theme.spacing * 2
    clip: true // squeezed below its icons, it is cut rather than drawn over the buttons

    function levelColour(level) {
        return level === GlanceStatus.Ok ? theme.okText
             : level === GlanceStatus.Warning ? theme.warningText
             : level === GlanceStatus.Problem ? theme.problemText : theme.missingText
    }

    component Glance: RowLayout {
        id: glance
        required property string key
        required property string icon
        required property string text
        required property int level
        property string tip
        objectName: "glance_" + key
        spacing: bar.theme.smallSpacing
        // Each takes what it needs while there is room, and gives it up in turn (its words elide).
        Layout.fillWidth: true
        Layout.maximumWidth: Math.ceil(implicitWidth) // whole pixels: the layout rounds down
        Layout.minimumWidth: bar.theme.iconSize
        TintedIcon {
            objectName: "glanceIcon_" + glance.key
            name: glance.icon
            color: bar.levelColour(glance.level)
            implicitWidth: bar.theme.iconSize
            implicitHeight: bar.theme.iconSize
        }
        Label {
            textFormat: Text.PlainText
            objectName: "glanceText_" + glance.key
            text: glance.text
            color: bar.levelColour(glance.level)
            font.bold: glance.level === GlanceStatus.Problem
            elide: Text.ElideRight
            Layout.fillWidth: true
            Layout.minimumWidth: 0
            Layout.preferredWidth: Math.ceil(implicitWidth)
            Layout.maximumWidth: Math.min(Math.ceil(implicitWidth), 220)
            HoverHandler { id: hover }
            ToolTip.visible: hover.hovered && glance.tip.length > 0
            ToolTip.text: glance.tip
        }
    }

    Glance {
        key: "connection"
        icon: "network-server"
        text: bar.status.connectionText
        level: bar.status.connectionLevel
        tip: qsTr("The connection to the server")
    }
    Glance {
        key: "vehicle"
        icon: "airplane-mode"
        text: bar.status.vehicleText
        level: bar.status.vehicleLevel
        tip: qsTr("The vehicle chosen in the fly view, else the first")
    }
    Glance {
        key: "gps"
        icon: bar.status.gpsIcon
        text: bar.status.gpsText
        level: bar.status.gpsLevel
        tip: qsTr("Its GPS: the fix and the satellites in view")
    }
    Glance {
        key: "battery"
        icon: bar.status.batteryIcon
        text: bar.status.batteryText
        level: bar.status.batteryLevel
        tip: qsTr("Its battery, against the low and critical levels")
    }
    Glance {
        key: "link"
        icon: bar.status.linkIcon
        text: bar.status.linkText
        level: bar.status.linkLevel
        tip: qsTr("Its link: how often its position arrives")
    }
}
