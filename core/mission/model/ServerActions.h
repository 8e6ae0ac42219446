#pragma once

#include "WaypointAction.h"

#include <QString>
#include <QVariant>

#include <optional>
#include <vector>

namespace sortie::mission {

// The actions Sortie keeps in the server's own terms (ServerAction: servos, VTOL transitions, lidar,
// hop, drop, and whatever a newer schema adds to ActionDefinition), described by the protobuf schema
// itself: a kind is a member of ActionDefinition, its fields are that member's scalars. Sortie's own
// knowledge only adds labels, units and ranges; an unknown member still gets a working editor.
// Only ServerActions.cpp reads the schema: what it hands out are plain values.
struct ServerActionField
{
    enum class Type { Real, Integer, Boolean, Choice };
    int number = 0;                                    // the field's number in the member's message
    Type type = Type::Real;
    QString name;                                      // the wire name: "servoId", "targetState"
    QString label;                                     // "Servo", "Recording"
    QString unit;                                      // "µs", "m", "s", ""
    std::optional<double> minimum, maximum;
    std::vector<std::pair<QString, QString>> choices;  // an enum's value names and labels
};

struct ServerActionKind
{
    int member = 0;                                             // ActionDefinition's field number
    QString kind;                                               // "setServo", "drop"
    QString label;                                              // "Set servo", "Drop payload"
    std::vector<ServerActionField> fields;                      // in the schema's order
};

// Every member of ActionDefinition Sortie has no type of its own for, in the schema's order.
const std::vector<ServerActionKind> &serverActionKinds();
const ServerActionKind *findServerActionKind(const QString &kind);
// The kind an action holds; nullptr when it holds none Sortie can name.
const ServerActionKind *serverActionKindOf(const ServerAction &action);

// A new action of that kind, every field unset (the server's defaults apply).
ServerAction newServerAction(const ServerActionKind &kind);
// A field's value: double, int or bool, or the enum value's name; invalid when the field is not set.
QVariant serverActionValue(const ServerAction &action, const ServerActionKind &kind, const ServerActionField &field);
// Sets (or, for an invalid or empty value, clears) a field. False when the value does not fit the
// field's type (a fraction for an integer, an unknown enum name). Other fields and unknown bytes stay.
bool setServerActionValue(ServerAction &action, const ServerActionKind &kind, const ServerActionField &field,
                          const QVariant &value);

// By names, for code that knows the kind: an action of `kind` with `values` set (nullopt when the
// kind is unknown or a value does not fit), and a field's value (invalid when unset or not there).
std::optional<ServerAction> makeServerAction(const QString &kind, const QVariantMap &values);
QVariant serverActionValue(const ServerAction &action, const QString &field);

// "Set servo: servo 3, PWM 1500 µs", "Drop payload".
QString describeServerAction(const ServerAction &action);

// The action whose definition `bytes` are (a serialized ActionDefinition, as a file keeps it);
// nullopt when they are not one.
std::optional<ServerAction> serverActionFromBytes(const QByteArray &bytes);

} // namespace sortie::mission
