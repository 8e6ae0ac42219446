#pragma once

#include "WaypointAction.h"

#include <QVariantMap>

#include <optional>
#include <vector>

namespace sortie::mission {

// Actions as QVariantMaps for QML: {"kind": "wait", "seconds": 5}, {"kind": "cameraSeriesByDistance",
// "intervalMeters": 20, "shots": 0, "startDelaySeconds": 0}, ... Keys are the C++ field names.
QVariantMap actionToVariant(const WaypointAction &action);
// nullopt for an unknown kind or a value a server action's field cannot hold; missing keys take the
// action's defaults. A server action (setServo, drop, ...) edits `base`'s definition when `base` is
// one of the same kind, so what the map does not name (ids, unknown fields) is kept.
std::optional<WaypointAction> actionFromVariant(const QVariantMap &map, const WaypointAction *base = nullptr);

// What an editor shows of an action kind: its fields by the keys above, with label, unit, type
// and range. The ranges are what a value must satisfy to be applied.
struct ActionField
{
    enum class Type { Number, Integer, Toggle, Choice };
    QString name;
    QString label;
    Type type = Type::Number;
    QString unit;                                    // "s", "m", "°", "°/s", ""
    std::optional<double> minimum, maximum;
    std::vector<std::pair<QString, QString>> choices; // value, label
    bool optional = false;                            // may be left unset (empty)
    // Why `value` cannot be this field's ("" when it can).
    QString check(const QVariant &value) const;
};

struct ActionKindDescription
{
    QString kind;    // actionKindName()
    QString label;   // "Photos by distance"
    std::vector<ActionField> fields;
};

// Every kind an operator can add, in menu order: Sortie's own, then the server's (ServerActions.h).
const std::vector<ActionKindDescription> &editableActionKinds();
const ActionKindDescription *actionKindDescription(const QString &kind);

// The operator's words for a label, unit or choice of the tables above (and ServerActions'): they
// keep the English source text, so that they stay the same values however the UI is translated.
QString actionText(const QString &source);

} // namespace sortie::mission
