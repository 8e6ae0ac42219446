import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Chooses where map tiles come from: the built-in offline base map, a web tile server (XYZ
// URL template, cached on disk) or an MBTiles file.
Dialog {
    id: dialog
    required property AppSettings appSettings
    title: qsTr("Map source")
    modal: true
    standardButtons: Dialog.Ok | Dialog.Cancel
    anchors.centerIn: Overlay.overlay
    width: Math.min(parent ? parent.width - 80 : 560, 560)

    onAboutToShow: {
        offline.checked = appSettings.mapSource === "offline"
        web.checked = appSettings.mapSource === "xyz"
        file.checked = appSettings.mapSource === "mbtiles"
        urlField.text = appSettings.tileUrlTemplate
        fileField.text = appSettings.mbtilesFile
    }
    onAccepted: {
        appSettings.tileUrlTemplate = urlField.text
        appSettings.mbtilesFile = fileField.text
        appSettings.mapSource = web.checked ? "xyz" : file.checked ? "mbtiles" : "offline"
    }

    ColumnLayout {
        anchors.fill: parent
        spacing: 8
        RadioButton {
            id: offline
            objectName: "offlineSource"
            text: qsTr("Offline base map (land outlines, always available)")
        }
        RadioButton {
            id: web
            objectName: "webSource"
            text: qsTr("Web tiles from a URL template")
        }
        TextField {
            id: urlField
            objectName: "urlTemplateField"
            Layout.fillWidth: true
            Layout.leftMargin: 28
            enabled: web.checked
            placeholderText: "https://tile.example.org/{z}/{x}/{y}.png"
            selectByMouse: true
            ToolTip.visible: hovered
            ToolTip.text: qsTr("{z}, {x} and {y} (or {-y}) are replaced per tile; {s} by a subdomain")
        }
        RadioButton {
            id: file
            objectName: "mbtilesSource"
            text: qsTr("MBTiles file (offline raster tiles)")
        }
        TextField {
            id: fileField
            objectName: "mbtilesField"
            Layout.fillWidth: true
            Layout.leftMargin: 28
            enabled: file.checked
            placeholderText: qsTr("/path/to/area.mbtiles")
            selectByMouse: true
        }
    }
}
