#pragma once

#include <QString>
#include <QVariant>

#include <memory>
#include <optional>
#include <vector>

namespace google::protobuf { class FieldDescriptor; }
namespace com::ugcs::ucs::proto { class ActionDefinition; }

namespace sortie::mission {

// The actions Sortie keeps in the server's own terms (ServerAction: servos, VTOL transitions, lidar,
// hop, drop, and whatever a newer schema adds to ActionDefinition), described by the protobuf schema
// itself: a kind is a member of ActionDefinition, its fields are that member's scalars. Sortie's own
// knowledge only adds labels, units and ranges; an unknown member still gets a working editor.
struct ServerActionField
{
    const google::protobuf::FieldDescriptor *descriptor = nullptr;
    QString name;                                      // the wire name: "servoId", "targetState"
    QString label;                                     // "Servo", "Recording"
    QString unit;                                      // "µs", "m", "s", ""
    std::optional<double> minimum, maximum;
    std::vector<std::pair<QString, QString>> choices;  // an enum's value names and labels
};

struct ServerActionKind
{
    const google::protobuf::FieldDescriptor *member = nullptr;  // ActionDefinition's field
    QString kind;                                               // "setServo", "drop"
    QString label;                                              // "Set servo", "Drop payload"
    std::vector<ServerActionField> fields;                      // in the schema's order
};

// Every member of ActionDefinition Sortie has no type of its own for, in the schema's order.
const std::vector<ServerActionKind> &serverActionKinds();
const ServerActionKind *findServerActionKind(const QString &kind);
// The kind a definition holds; nullptr when it holds none Sortie can name.
const ServerActionKind *serverActionKindOf(const com::ugcs::ucs::proto::ActionDefinition &definition);

// A new definition of that kind, every field unset (the server's defaults apply).
std::shared_ptr<com::ugcs::ucs::proto::ActionDefinition> newServerAction(const ServerActionKind &kind);
// A field's value: double, int or bool, or the enum value's name; invalid when the field is not set.
QVariant serverActionValue(const com::ugcs::ucs::proto::ActionDefinition &definition, const ServerActionKind &kind,
                           const ServerActionField &field);
// Sets (or, for an invalid or empty value, clears) a field. False when the value does not fit the
// field's type (a fraction for an integer, an unknown enum name). Other fields and unknown bytes stay.
bool setServerActionValue(com::ugcs::ucs::proto::ActionDefinition &definition, const ServerActionKind &kind,
                          const ServerActionField &field, const QVariant &value);

// By names, for code that knows the kind: a definition of `kind` with `values` set (nullptr when the
// kind is unknown or a value does not fit), and a field's value (invalid when unset or not there).
std::shared_ptr<com::ugcs::ucs::proto::ActionDefinition> makeServerAction(const QString &kind, const QVariantMap &values);
QVariant serverActionValue(const com::ugcs::ucs::proto::ActionDefinition &definition, const QString &field);

// "Set servo: servo 3, PWM 1500 µs", "Drop payload".
QString describeServerAction(const com::ugcs::ucs::proto::ActionDefinition &definition);

} // namespace sortie::mission
