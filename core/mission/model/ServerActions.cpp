#include "ServerActions.h"

#include "Domain.pb.h"

#include <QCoreApplication>
#include <QStringList>

#include <cmath>
#include <limits>

namespace sortie::mission {

namespace pb = com::ugcs::ucs::proto;
using google::protobuf::Descriptor;
using google::protobuf::FieldDescriptor;

namespace {

// ActionDefinition's members that are not actions, or that Sortie models with types of its own.
bool isModelledOrNotAnAction(const std::string &member)
{
    static const char *const names[] = {"segmentDefinition", "waitDefinition", "poiDefinition", "headingDefinition",
                                        "cameraControlDefinition", "cameraTriggerDefinition", "cameraSeriesByTimeDefinition",
                                        "cameraSeriesByDistanceDefinition", "panoramaDefinition"};
    for (const char *n : names)
        if (member == n)
            return true;
    return false;
}

// "descentAltitude" -> "Descent altitude"; "RS_ON" (after its prefix) -> "On".
QString humanized(const QString &name)
{
    QString out;
    for (int i = 0; i < name.size(); ++i) {
        const QChar c = name[i];
        if (c == u'_') { out += u' '; continue; }
        if (i > 0 && c.isUpper() && name[i - 1].isLower())
            out += u' ';
        out += out.isEmpty() ? c.toUpper() : c.toLower();
    }
    return out;
}

QString enumLabel(const std::string &valueName)
{
    const auto underscore = valueName.find('_');
    return humanized(QString::fromStdString(underscore == std::string::npos ? valueName : valueName.substr(underscore + 1)));
}

// "setServoDefinition" -> "setServo"; "DropDefinition" -> "drop".
QString kindName(const FieldDescriptor *member)
{
    QString kind = QString::fromStdString(member->name());
    if (kind.endsWith(QLatin1String("Definition")))
        kind.chop(10);
    if (!kind.isEmpty())
        kind[0] = kind[0].toLower();
    return kind;
}

struct Known { const char *kind; const char *field; const char *label; const char *unit; std::optional<double> minimum, maximum; };

// What Sortie knows better than a field's name. Labels and units are kept in English (the source
// text) and translated where shown (actionText(), describeServerAction()), in the context
// "ActionVariants" that the editable actions' labels share. Units follow from the names (UgCS publishes none for
// these); PWM is a pulse width in microseconds, as MAVLink's DO_SET_SERVO takes it.
const Known kKnown[] = {
    {"setServo", nullptr, QT_TRANSLATE_NOOP("ActionVariants", "Set servo"), "", {}, {}},
    {"setServo", "servoId", QT_TRANSLATE_NOOP("ActionVariants", "Servo"), "", 0, 255},
    {"setServo", "pwm", QT_TRANSLATE_NOOP("ActionVariants", "PWM"), "µs", 0, 65535},
    {"repeatServo", nullptr, QT_TRANSLATE_NOOP("ActionVariants", "Repeat servo"), "", {}, {}},
    {"repeatServo", "servoId", QT_TRANSLATE_NOOP("ActionVariants", "Servo"), "", 0, 255},
    {"repeatServo", "pwm", QT_TRANSLATE_NOOP("ActionVariants", "PWM"), "µs", 0, 65535},
    {"repeatServo", "delay", QT_TRANSLATE_NOOP("ActionVariants", "Cycle time"), QT_TRANSLATE_NOOP("ActionVariants", "s"), 0, 3600},
    {"repeatServo", "count", QT_TRANSLATE_NOOP("ActionVariants", "Repeats"), "", 0, 100000},
    {"transitionVtol", nullptr, QT_TRANSLATE_NOOP("ActionVariants", "Switch to hover (VTOL)"), "", {}, {}},
    {"transitionFixed", nullptr, QT_TRANSLATE_NOOP("ActionVariants", "Switch to fixed-wing"), "", {}, {}},
    {"lidarRecordingControl", nullptr, QT_TRANSLATE_NOOP("ActionVariants", "Lidar recording"), "", {}, {}},
    {"lidarRecordingControl", "targetState", QT_TRANSLATE_NOOP("ActionVariants", "Recording"), "", {}, {}},
    {"lidarCalibration", nullptr, QT_TRANSLATE_NOOP("ActionVariants", "Lidar calibration"), "", {}, {}},
    {"lidarCalibration", "distance", QT_TRANSLATE_NOOP("ActionVariants", "Distance"), QT_TRANSLATE_NOOP("ActionVariants", "m"), 0, 10000},
    {"lidarCalibration", "times", QT_TRANSLATE_NOOP("ActionVariants", "Times"), "", 0, 1000},
    {"hopAction", nullptr, QT_TRANSLATE_NOOP("ActionVariants", "Hop"), "", {}, {}},
    {"hopAction", "descentAltitude", QT_TRANSLATE_NOOP("ActionVariants", "Descent altitude"), QT_TRANSLATE_NOOP("ActionVariants", "m"), 0, 10000},
    {"hopAction", "waitTime", QT_TRANSLATE_NOOP("ActionVariants", "Wait"), QT_TRANSLATE_NOOP("ActionVariants", "s"), 0, 86400},
    {"hopAction", "dropAction", QT_TRANSLATE_NOOP("ActionVariants", "Drop payload"), "", {}, {}},
    {"hopAction", "descentSpeed", QT_TRANSLATE_NOOP("ActionVariants", "Descent speed"), QT_TRANSLATE_NOOP("ActionVariants", "m/s"), 0, 100},
    {"drop", nullptr, QT_TRANSLATE_NOOP("ActionVariants", "Drop payload"), "", {}, {}},
};

const Known *known(const QString &kind, const char *field)
{
    for (const Known &k : kKnown)
        if (kind == QLatin1String(k.kind) && ((!field && !k.field) || (field && k.field && qstrcmp(field, k.field) == 0)))
            return &k;
    return nullptr;
}

bool editable(const FieldDescriptor *f)
{
    if (f->is_repeated() || f->name() == "id" || f->name() == "version")
        return false;
    switch (f->cpp_type()) {
    case FieldDescriptor::CPPTYPE_DOUBLE:
    case FieldDescriptor::CPPTYPE_FLOAT:
    case FieldDescriptor::CPPTYPE_INT32:
    case FieldDescriptor::CPPTYPE_INT64:
    case FieldDescriptor::CPPTYPE_UINT32:
    case FieldDescriptor::CPPTYPE_UINT64:
    case FieldDescriptor::CPPTYPE_BOOL:
    case FieldDescriptor::CPPTYPE_ENUM:
        return true;
    default:
        return false;  // tags, names and nested messages are kept, not edited
    }
}

ServerActionField::Type typeOf(const FieldDescriptor *f)
{
    switch (f->cpp_type()) {
    case FieldDescriptor::CPPTYPE_BOOL: return ServerActionField::Type::Boolean;
    case FieldDescriptor::CPPTYPE_ENUM: return ServerActionField::Type::Choice;
    case FieldDescriptor::CPPTYPE_DOUBLE:
    case FieldDescriptor::CPPTYPE_FLOAT: return ServerActionField::Type::Real;
    default: return ServerActionField::Type::Integer;
    }
}

ServerActionKind describe(const FieldDescriptor *member)
{
    ServerActionKind kind;
    kind.member = member->number();
    kind.kind = kindName(member);
    const Known *k = known(kind.kind, nullptr);
    kind.label = k ? QString::fromUtf8(k->label) : humanized(kind.kind);
    const Descriptor *message = member->message_type();
    for (int i = 0; i < message->field_count(); ++i) {
        const FieldDescriptor *f = message->field(i);
        if (!editable(f))
            continue;
        ServerActionField field;
        field.number = f->number();
        field.type = typeOf(f);
        field.name = QString::fromStdString(f->name());
        if (const Known *kf = known(kind.kind, f->name().c_str())) {
            field.label = QString::fromUtf8(kf->label);
            field.unit = QString::fromUtf8(kf->unit);
            field.minimum = kf->minimum;
            field.maximum = kf->maximum;
        } else {
            field.label = humanized(field.name);
        }
        if (f->cpp_type() == FieldDescriptor::CPPTYPE_UINT32 || f->cpp_type() == FieldDescriptor::CPPTYPE_UINT64)
            field.minimum = field.minimum.value_or(0.0);
        if (const auto *e = f->enum_type())
            for (int v = 0; v < e->value_count(); ++v)
                field.choices.emplace_back(QString::fromStdString(e->value(v)->name()), enumLabel(e->value(v)->name()));
        kind.fields.push_back(std::move(field));
    }
    return kind;
}

const FieldDescriptor *memberField(const ServerActionKind &kind)
{
    return pb::ActionDefinition::descriptor()->FindFieldByNumber(kind.member);
}

const FieldDescriptor *fieldOf(const ServerActionKind &kind, const ServerActionField &field)
{
    return memberField(kind)->message_type()->FindFieldByNumber(field.number);
}

const google::protobuf::Message *memberOf(const pb::ActionDefinition &d, const ServerActionKind &kind)
{
    const auto *refl = d.GetReflection();
    const FieldDescriptor *member = memberField(kind);
    return refl->HasField(d, member) ? &refl->GetMessage(d, member) : nullptr;
}

// The definition an action holds: its bytes parsed (an action without bytes holds an empty one).
pb::ActionDefinition definitionOf(const ServerAction &action)
{
    pb::ActionDefinition d;
    d.ParseFromArray(action.definition.constData(), int(action.definition.size()));
    return d;
}

ServerAction actionOf(const pb::ActionDefinition &d)
{
    return ServerAction{QByteArray::fromStdString(d.SerializeAsString())};
}

const ServerActionKind *kindOf(const pb::ActionDefinition &definition)
{
    for (const ServerActionKind &k : serverActionKinds())
        if (memberOf(definition, k))
            return &k;
    return nullptr;
}

QVariant valueOf(const pb::ActionDefinition &definition, const ServerActionKind &kind, const ServerActionField &field)
{
    const auto *m = memberOf(definition, kind);
    if (!m)
        return {};
    const auto *refl = m->GetReflection();
    const FieldDescriptor *f = fieldOf(kind, field);
    if (!refl->HasField(*m, f))
        return {};  // not set: shown as missing, never as the schema's 0
    switch (f->cpp_type()) {
    case FieldDescriptor::CPPTYPE_DOUBLE: return refl->GetDouble(*m, f);
    case FieldDescriptor::CPPTYPE_FLOAT: return double(refl->GetFloat(*m, f));
    case FieldDescriptor::CPPTYPE_INT32: return refl->GetInt32(*m, f);
    case FieldDescriptor::CPPTYPE_INT64: return qlonglong(refl->GetInt64(*m, f));
    case FieldDescriptor::CPPTYPE_UINT32: return uint(refl->GetUInt32(*m, f));
    case FieldDescriptor::CPPTYPE_UINT64: return qulonglong(refl->GetUInt64(*m, f));
    case FieldDescriptor::CPPTYPE_BOOL: return refl->GetBool(*m, f);
    case FieldDescriptor::CPPTYPE_ENUM: return QString::fromStdString(refl->GetEnum(*m, f)->name());
    default: return {};
    }
}

bool setValue(pb::ActionDefinition &definition, const ServerActionKind &kind, const ServerActionField &field,
              const QVariant &value)
{
    auto *m = definition.GetReflection()->MutableMessage(&definition, memberField(kind));
    const auto *refl = m->GetReflection();
    const FieldDescriptor *f = fieldOf(kind, field);
    if (!value.isValid() || (value.typeId() == QMetaType::QString && value.toString().trimmed().isEmpty())) {
        refl->ClearField(m, f);
        return true;
    }
    if (f->cpp_type() == FieldDescriptor::CPPTYPE_BOOL) {
        refl->SetBool(m, f, value.toBool());
        return true;
    }
    if (f->cpp_type() == FieldDescriptor::CPPTYPE_ENUM) {
        const auto *v = f->enum_type()->FindValueByName(value.toString().toStdString());
        if (!v)
            return false;
        refl->SetEnum(m, f, v);
        return true;
    }
    bool ok = false;
    const double v = value.toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return false;
    const auto whole = [v](double lo, double hi) { return std::floor(v) == v && v >= lo && v <= hi; };
    switch (f->cpp_type()) {
    case FieldDescriptor::CPPTYPE_DOUBLE: refl->SetDouble(m, f, v); return true;
    case FieldDescriptor::CPPTYPE_FLOAT: refl->SetFloat(m, f, float(v)); return true;
    case FieldDescriptor::CPPTYPE_INT32:
        if (!whole(std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max())) return false;
        refl->SetInt32(m, f, int32_t(v)); return true;
    case FieldDescriptor::CPPTYPE_INT64:
        if (!whole(-9007199254740992.0, 9007199254740992.0)) return false;
        refl->SetInt64(m, f, int64_t(v)); return true;
    case FieldDescriptor::CPPTYPE_UINT32:
        if (!whole(0, std::numeric_limits<uint32_t>::max())) return false;
        refl->SetUInt32(m, f, uint32_t(v)); return true;
    case FieldDescriptor::CPPTYPE_UINT64:
        if (!whole(0, 9007199254740992.0)) return false;
        refl->SetUInt64(m, f, uint64_t(v)); return true;
    default: return false;
    }
}

QString number(double v) { return QString::number(v, 'g', 10); }

} // namespace

const std::vector<ServerActionKind> &serverActionKinds()
{
    static const std::vector<ServerActionKind> kinds = [] {
        std::vector<ServerActionKind> list;
        const Descriptor *d = pb::ActionDefinition::descriptor();
        for (int i = 0; i < d->field_count(); ++i) {
            const FieldDescriptor *f = d->field(i);
            if (f->cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE && !f->is_repeated() && !isModelledOrNotAnAction(f->name()))
                list.push_back(describe(f));
        }
        return list;
    }();
    return kinds;
}

const ServerActionKind *findServerActionKind(const QString &kind)
{
    for (const ServerActionKind &k : serverActionKinds())
        if (k.kind == kind)
            return &k;
    return nullptr;
}

const ServerActionKind *serverActionKindOf(const ServerAction &action)
{
    return kindOf(definitionOf(action));
}

ServerAction newServerAction(const ServerActionKind &kind)
{
    pb::ActionDefinition d;
    d.GetReflection()->MutableMessage(&d, memberField(kind));  // present, even with no field set
    return actionOf(d);
}

QVariant serverActionValue(const ServerAction &action, const ServerActionKind &kind, const ServerActionField &field)
{
    return valueOf(definitionOf(action), kind, field);
}

bool setServerActionValue(ServerAction &action, const ServerActionKind &kind, const ServerActionField &field,
                          const QVariant &value)
{
    pb::ActionDefinition d = definitionOf(action);
    if (!setValue(d, kind, field, value))
        return false;
    action = actionOf(d);
    return true;
}

std::optional<ServerAction> makeServerAction(const QString &kind, const QVariantMap &values)
{
    const ServerActionKind *k = findServerActionKind(kind);
    if (!k)
        return std::nullopt;
    pb::ActionDefinition d;
    d.GetReflection()->MutableMessage(&d, memberField(*k));
    for (const ServerActionField &f : k->fields)
        if (values.contains(f.name) && !setValue(d, *k, f, values.value(f.name)))
            return std::nullopt;
    return actionOf(d);
}

QVariant serverActionValue(const ServerAction &action, const QString &field)
{
    const pb::ActionDefinition d = definitionOf(action);
    if (const ServerActionKind *k = kindOf(d))
        for (const ServerActionField &f : k->fields)
            if (f.name == field)
                return valueOf(d, *k, f);
    return {};
}

QString describeServerAction(const ServerAction &action)
{
    const pb::ActionDefinition definition = definitionOf(action);
    const ServerActionKind *kind = kindOf(definition);
    if (!kind)
        return QCoreApplication::translate("ServerAction", "Server action");
    QStringList parts;
    for (const ServerActionField &f : kind->fields) {
        const QVariant v = valueOf(definition, *kind, f);
        if (!v.isValid())
            continue;
        const QString shown = QCoreApplication::translate("ActionVariants", f.label.toUtf8().constData());
        const QString label = shown == shown.toUpper() ? shown : shown.toLower();  // "PWM" stays
        QString text;
        if (v.typeId() == QMetaType::Bool)
            text = v.toBool() ? label : QString();
        else if (!f.choices.empty()) {
            for (const auto &[name, choice] : f.choices)
                if (name == v.toString())
                    text = label + u' ' + choice.toLower();
        } else
            text = (label + u' ' + number(v.toDouble()) + u' ' + QCoreApplication::translate("ActionVariants", f.unit.toUtf8().constData())).trimmed();
        if (!text.isEmpty())
            parts << text;
    }
    const QString kindLabel = QCoreApplication::translate("ActionVariants", kind->label.toUtf8().constData());
    return parts.isEmpty() ? kindLabel : kindLabel + QStringLiteral(": ") + parts.join(QStringLiteral(", "));
}

std::optional<ServerAction> serverActionFromBytes(const QByteArray &bytes)
{
    pb::ActionDefinition d;
    if (bytes.isEmpty() || !d.ParseFromArray(bytes.constData(), int(bytes.size())))
        return std::nullopt;
    return ServerAction{bytes};
}

} // namespace sortie::mission
