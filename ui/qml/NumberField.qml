import QtQuick
import QtQuick.Controls
import Sortie.Ui

// A field for a number as the operator reads and types it: shown in the language's format ("40,5"
// in German, again after a change of language), read in it or with a dot (DisplayUnits.parseNumber). `number` is undefined while the text is no number or is
// outside from..to. Leaving the field (or Enter) with such text turns it red with the reason, and
// nothing is taken from it; `numberEntered` carries an accepted number.
TextField {
    id: field
    required property Theme theme
    required property DisplayUnits units
    property var value               // the number shown; undefined or NaN: empty
    property int decimals: -1        // places shown; -1: the shortest exact text
    property bool plainDot: false    // coordinates: always "56.976500", as DisplayUnits shows them
    property real from: -Infinity
    property real to: Infinity
    readonly property var parsed: units.parseNumber(text)
    readonly property var number: parsed !== undefined && parsed >= from && parsed <= to ? parsed : undefined
    property bool allowEmpty: false // empty is "nothing typed yet" rather than a mistake
    property bool refused: false    // shown red; cleared by the next keystroke
    signal numberEntered(real number)

    // units.language: a change of language re-formats the number (the call alone is no dependency).
    text: value === undefined || isNaN(value) ? ""
        : plainDot ? Number(value).toFixed(decimals < 0 ? 6 : decimals)
        : (units.language, units.formatNumber(value, decimals))
    selectByMouse: true
    color: refused ? field.theme.problemText : palette.text  // the theme's problem words: readable on every scheme's fields
    onTextEdited: refused = false
    onEditingFinished: {
        if (readOnly || allowEmpty && text.trim() === "") {
            refused = false
            return
        }
        refused = number === undefined
        if (!refused)
            numberEntered(number)
    }
    property string hint  // what the field is, shown on hover
    readonly property string reason: parsed === undefined
                  ? qsTr("Not a number: type it as %1").arg(units.formatNumber(12.5, 1))
                  : isFinite(from) && isFinite(to) ? qsTr("From %1 to %2").arg(units.formatNumber(from)).arg(units.formatNumber(to))
                  : isFinite(from) ? qsTr("At least %1").arg(units.formatNumber(from))
                  : qsTr("At most %1").arg(units.formatNumber(to))
    ToolTip.visible: refused && (hovered || activeFocus) || hovered && hint.length > 0
    ToolTip.text: refused ? reason : hint
}
