#pragma once

#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QVariant>
#include <QVariantList>

namespace sortie::mission {

// One field of a waypoint action as its editor shows it (WaypointActionsModel's `fields`): what it
// is, its value and, for a choice, the choices worded for the operator with the one chosen. A value
// the action leaves unset is no value (`hasValue` false, `text` empty), never a 0.
struct ActionFieldRow
{
    Q_GADGET
    Q_PROPERTY(int action MEMBER action)        // the action's row in the model
    Q_PROPERTY(QString name MEMBER name)        // the field, for WaypointActionsModel::setField
    Q_PROPERTY(QString label MEMBER label)
    Q_PROPERTY(QString unit MEMBER unit)
    Q_PROPERTY(bool number READ isNumber)       // typed into a field (a number or an integer)
    Q_PROPERTY(bool toggle READ isToggle)
    Q_PROPERTY(bool choice READ isChoice)
    Q_PROPERTY(QVariant value MEMBER value)     // what setField takes back: a number, a bool, a choice's value
    Q_PROPERTY(bool hasValue READ hasValue)
    Q_PROPERTY(QString text MEMBER text)        // a number as typed, "" when unset
    Q_PROPERTY(bool on READ isOn)               // a toggle's state
    Q_PROPERTY(QStringList choiceTexts MEMBER choiceTexts)
    Q_PROPERTY(QStringList choiceValues MEMBER choiceValues)
    Q_PROPERTY(int choiceIndex MEMBER choiceIndex)  // -1: none chosen
    Q_PROPERTY(bool optional MEMBER optional)

public:
    enum class Kind { Number, Integer, Toggle, Choice };

    int action = -1;
    QString name, label, unit;
    Kind kind = Kind::Number;
    QVariant value;
    QString text;
    QStringList choiceTexts;
    QStringList choiceValues;
    int choiceIndex = -1;
    bool optional = false;

    bool isNumber() const { return kind == Kind::Number || kind == Kind::Integer; }
    bool isToggle() const { return kind == Kind::Toggle; }
    bool isChoice() const { return kind == Kind::Choice; }
    bool hasValue() const { return value.isValid() && !value.isNull(); }
    bool isOn() const { return isToggle() && value.toBool(); }
    bool operator==(const ActionFieldRow &) const = default;
};

// An action the "add" menu offers: its kind for WaypointActionsModel::add, and its name.
struct ActionKindChoice
{
    Q_GADGET
    Q_PROPERTY(QString kind MEMBER kind)
    Q_PROPERTY(QString label MEMBER label)

public:
    QString kind, label;
    bool operator==(const ActionKindChoice &) const = default;
};

} // namespace sortie::mission
