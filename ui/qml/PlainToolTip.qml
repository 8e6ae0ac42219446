import QtQuick
import QtQuick.Controls

// A tool tip whose text is shown as it is, never as HTML: for text from outside (a zone's name and
// source under the mouse), which at Qt's default (AutoText) could fetch an image or fake a status
// (issue 36). The style's own content item keeps its look; only its format is set.
ToolTip {
    Component.onCompleted: contentItem.textFormat = Text.PlainText
}
