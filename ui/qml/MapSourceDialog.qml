import QtQuick
import QtQuick.Controls
import QtQuick.Dialogs
import QtQuick.Layouts
import Sortie.Ui

// Chooses where map tiles come from: the built-in offline base map, a web tile server (XYZ
// URL template, cached on disk) or an MBTiles file; and the operator's own rasters: an orthophoto
// drawn over the base map (with its opacity) and a DEM file or folder for the terrain. A raster
// GDAL cannot use shows GDAL's reason (RasterFileCheck) and OK waits until it is fixed or cleared.
// Each raster path can be typed or picked (a file dialog; for the DEM a file or a folder).
Dialog {
    id: dialog
    // Its colours; the window hands its own (a dialog shown alone follows the system's).
    property Theme theme: Theme {}
    required property AppSettings appSettings
    title: qsTr("Map source")
    modal: true
    standardButtons: Dialog.Ok | Dialog.Cancel
    anchors.centerIn: Overlay.overlay
    width: Math.min(parent ? parent.width - 80 : 560, 560)

    readonly property string orthophotoProblem: rasterCheck.orthophotoProblem(orthophotoField.text)
    readonly property demCheck demCheck: rasterCheck.checkDem(demField.text)
    readonly property string demProblem: demCheck.problem
    readonly property bool rastersUsable: orthophotoProblem === "" && demProblem === ""

    RasterFileCheck { id: rasterCheck }

    // parentWindow is bound: a picker created before its scene is shown finds no window itself (Qt 6.4).
    FileDialog {
        id: orthophotoPicker
        objectName: "orthophotoPicker"
        parentWindow: orthophotoField.Window.window  // the dialog's window, once it has one
        title: qsTr("Orthophoto")
        nameFilters: [qsTr("Rasters (*.tif *.tiff *.jp2 *.vrt *.img *.ecw *.sid *.png *.jpg)"), qsTr("All files (*)")]
        onAccepted: orthophotoField.text = rasterCheck.localPath(selectedFile.toString())
    }
    FileDialog {
        id: demFilePicker
        objectName: "demFilePicker"
        parentWindow: orthophotoField.Window.window  // the dialog's window, once it has one
        title: qsTr("Terrain model (DEM)")
        nameFilters: [qsTr("Elevation rasters (*.tif *.tiff *.hgt *.vrt *.dt0 *.dt1 *.dt2 *.asc *.img *.bil *.flt *.dem)"), qsTr("All files (*)")]
        onAccepted: demField.text = rasterCheck.localPath(selectedFile.toString())
    }
    FolderDialog {
        id: demFolderPicker
        objectName: "demFolderPicker"
        parentWindow: orthophotoField.Window.window  // the dialog's window, once it has one
        title: qsTr("A folder of terrain models (DEM tiles)")
        onAccepted: demField.text = rasterCheck.localPath(selectedFolder.toString())
    }

    Component.onCompleted: standardButton(Dialog.Ok).enabled = Qt.binding(() => rastersUsable)

    onAboutToShow: {
        offline.checked = appSettings.mapSource === "offline"
        web.checked = appSettings.mapSource === "xyz"
        file.checked = appSettings.mapSource === "mbtiles"
        urlField.text = appSettings.tileUrlTemplate
        fileField.text = appSettings.mbtilesFile
        orthophotoField.text = appSettings.orthophotoFile
        opacitySlider.value = appSettings.orthophotoOpacity
        demField.text = appSettings.demPath
    }
    onAccepted: {
        appSettings.tileUrlTemplate = urlField.text
        appSettings.mbtilesFile = fileField.text
        appSettings.mapSource = web.checked ? "xyz" : file.checked ? "mbtiles" : "offline"
        appSettings.orthophotoFile = rasterCheck.localPath(orthophotoField.text.trim())
        appSettings.orthophotoOpacity = opacitySlider.value
        appSettings.demPath = rasterCheck.localPath(demField.text.trim())
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
        MenuSeparator { Layout.fillWidth: true }
        Label {
            textFormat: Text.PlainText
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            text: qsTr("Orthophoto over the base map (GeoTIFF or any raster GDAL reads, any CRS)")
        }
        RowLayout {
            Layout.fillWidth: true
            TextField {
                id: orthophotoField
                objectName: "orthophotoField"
                Layout.fillWidth: true
                placeholderText: qsTr("/path/to/orthophoto.tif (empty: none)")
                selectByMouse: true
            }
            Button {
                objectName: "orthophotoBrowse"
                text: qsTr("Browse…")
                onClicked: orthophotoPicker.open()
            }
        }
        Label {
            textFormat: Text.PlainText
            objectName: "orthophotoProblem"
            Layout.fillWidth: true
            visible: text.length > 0
            text: dialog.orthophotoProblem
            color: dialog.theme.problemText
            wrapMode: Text.Wrap
        }
        RowLayout {
            Label { textFormat: Text.PlainText; text: qsTr("Opacity") }
            Slider {
                id: opacitySlider
                objectName: "orthophotoOpacity"
                Layout.fillWidth: true
                from: 0.1
                to: 1.0
                stepSize: 0.05
            }
            Label { textFormat: Text.PlainText; text: qsTr("%1 %").arg(Math.round(opacitySlider.value * 100)) }
        }
        Label {
            textFormat: Text.PlainText
            Layout.fillWidth: true
            wrapMode: Text.Wrap
            text: qsTr("Terrain: a DEM file (GeoTIFF, .hgt, ...) or a folder of them")
        }
        RowLayout {
            Layout.fillWidth: true
            TextField {
                id: demField
                objectName: "demField"
                Layout.fillWidth: true
                placeholderText: qsTr("/path/to/dem.tif or /path/to/dem-folder (empty: none)")
                selectByMouse: true
            }
            Button {
                objectName: "demFileBrowse"
                text: qsTr("File…")
                onClicked: demFilePicker.open()
            }
            Button {
                objectName: "demFolderBrowse"
                text: qsTr("Folder…")
                onClicked: demFolderPicker.open()
            }
        }
        Label {
            textFormat: Text.PlainText
            objectName: "demProblem"
            Layout.fillWidth: true
            visible: text.length > 0
            text: dialog.demProblem
            color: dialog.theme.problemText
            wrapMode: Text.Wrap
        }
        Label {
            textFormat: Text.PlainText
            // A folder usable with a few bad files: which, and why (the rest still answers).
            objectName: "demLeftOut"
            Layout.fillWidth: true
            visible: text.length > 0
            text: dialog.demCheck.leftOut
            color: dialog.theme.warningText
            wrapMode: Text.Wrap
        }
    }
}
