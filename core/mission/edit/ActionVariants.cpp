#include "ActionVariants.h"

#include "ServerActions.h"

#include <QCoreApplication>

#include <cmath>

namespace sortie::mission {


namespace {
template<class... Ts> struct Overloaded : Ts... { using Ts::operator()...; };
template<class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

double num(const QVariantMap &m, const char *key, double fallback)
{
    const auto it = m.constFind(QLatin1String(key));
    bool ok = false;
    const double v = it == m.constEnd() ? fallback : it->toDouble(&ok);
    return ok ? v : fallback;
}

const char *triggerName(TriggerState s)
{
    switch (s) {
    case TriggerState::SingleShot: return "singleShot";
    case TriggerState::StartRecording: return "startRecording";
    case TriggerState::StopRecording: return "stopRecording";
    case TriggerState::ToggleRecording: return "toggleRecording";
    }
    return "singleShot";
}
}

QVariantMap actionToVariant(const WaypointAction &action)
{
    QVariantMap m = std::visit(Overloaded{
        [](const WaitAction &a) { return QVariantMap{{"seconds", a.seconds}, {"waitForOperator", a.waitForOperator}}; },
        [](const HeadingAction &a) { return QVariantMap{{"headingDeg", a.headingDeg}, {"relativeToNextWaypoint", a.relativeToNextWaypoint}}; },
        [](const PoiAction &a) {
            return QVariantMap{{"latitude", a.position.latitude}, {"longitude", a.position.longitude},
                               {"altitude", a.altitude}, {"altitudeType", altitudeTypeName(a.altitudeType)}};
        },
        [](const CameraTriggerAction &a) { return QVariantMap{{"state", QString::fromLatin1(triggerName(a.state))}}; },
        [](const CameraSeriesByTimeAction &a) {
            return QVariantMap{{"intervalSeconds", a.intervalSeconds}, {"shots", a.shots}, {"startDelaySeconds", a.startDelaySeconds}};
        },
        [](const CameraSeriesByDistanceAction &a) {
            return QVariantMap{{"intervalMeters", a.intervalMeters}, {"shots", a.shots}, {"startDelaySeconds", a.startDelaySeconds}};
        },
        [](const PanoramaAction &a) {
            return QVariantMap{{"angleDeg", a.angleDeg}, {"stepAngleDeg", a.stepAngleDeg}, {"stepDelaySeconds", a.stepDelaySeconds},
                               {"clockwise", a.direction == RotationDirection::Clockwise},
                               {"rotationSpeedDegPerSecond", a.rotationSpeedDegPerSecond},
                               {"video", a.mode == PanoramaMode::Video}};
        },
        [](const CameraControlAction &a) {
            QVariantMap m;  // a value not set has no key
            if (a.tiltDeg) m.insert(QStringLiteral("tiltDeg"), *a.tiltDeg);
            if (a.rollDeg) m.insert(QStringLiteral("rollDeg"), *a.rollDeg);
            if (a.yawDeg) m.insert(QStringLiteral("yawDeg"), *a.yawDeg);
            if (a.zoomLevel) m.insert(QStringLiteral("zoomLevel"), *a.zoomLevel);
            return m;
        },
        [](const ServerAction &a) {
            QVariantMap m;  // a field not set has no key
            if (const ServerActionKind *kind = serverActionKindOf(a))
                for (const ServerActionField &f : kind->fields)
                    if (const QVariant v = serverActionValue(a, *kind, f); v.isValid())
                        m.insert(f.name, v);
            return m;
        },
    }, action);
    m.insert(QStringLiteral("kind"), actionKindName(action));
    m.insert(QStringLiteral("summary"), describeAction(action));
    return m;
}

namespace {
// A server action of that kind: `base`'s definition when it is one (what Sortie does not edit stays,
// ids and unknown fields too), else a new one; every field the map names set from it.
std::optional<WaypointAction> serverActionFromVariant(const ServerActionKind &kind, const QVariantMap &m, const WaypointAction *base)
{
    const auto *was = base ? std::get_if<ServerAction>(base) : nullptr;
    const bool sameKind = was && serverActionKindOf(*was) == &kind;
    ServerAction action = sameKind ? *was : newServerAction(kind);
    for (const ServerActionField &f : kind.fields) {
        const QVariant v = m.value(f.name);
        if ((v.isValid() || sameKind) && !setServerActionValue(action, kind, f, v))
            return std::nullopt;
    }
    return action;
}
} // namespace

std::optional<WaypointAction> actionFromVariant(const QVariantMap &m, const WaypointAction *base)
{
    const QString kind = m.value(QStringLiteral("kind")).toString();
    if (const ServerActionKind *server = findServerActionKind(kind))
        return serverActionFromVariant(*server, m, base);
    if (kind == QLatin1String("wait"))
        return WaitAction{num(m, "seconds", 0), m.value(QStringLiteral("waitForOperator")).toBool()};
    if (kind == QLatin1String("heading"))
        return HeadingAction{num(m, "headingDeg", 0), m.value(QStringLiteral("relativeToNextWaypoint")).toBool()};
    if (kind == QLatin1String("poi")) {
        PoiAction a;
        a.position = {num(m, "latitude", 0), num(m, "longitude", 0)};
        a.altitude = num(m, "altitude", 0);
        parseAltitudeType(m.value(QStringLiteral("altitudeType"), QStringLiteral("AGL")).toString(), &a.altitudeType);
        return a;
    }
    if (kind == QLatin1String("cameraTrigger")) {
        CameraTriggerAction a;
        const QString s = m.value(QStringLiteral("state")).toString();
        for (TriggerState t : {TriggerState::SingleShot, TriggerState::StartRecording, TriggerState::StopRecording, TriggerState::ToggleRecording})
            if (s == QLatin1String(triggerName(t)))
                a.state = t;
        return a;
    }
    if (kind == QLatin1String("cameraSeriesByTime")) {
        CameraSeriesByTimeAction d;
        return CameraSeriesByTimeAction{num(m, "intervalSeconds", d.intervalSeconds), int(num(m, "shots", 0)), num(m, "startDelaySeconds", 0)};
    }
    if (kind == QLatin1String("cameraSeriesByDistance")) {
        CameraSeriesByDistanceAction d;
        return CameraSeriesByDistanceAction{num(m, "intervalMeters", d.intervalMeters), int(num(m, "shots", 0)), num(m, "startDelaySeconds", 0)};
    }
    if (kind == QLatin1String("panorama")) {
        PanoramaAction a;
        a.angleDeg = num(m, "angleDeg", a.angleDeg);
        a.stepAngleDeg = num(m, "stepAngleDeg", a.stepAngleDeg);
        a.stepDelaySeconds = num(m, "stepDelaySeconds", a.stepDelaySeconds);
        a.direction = m.value(QStringLiteral("clockwise"), true).toBool() ? RotationDirection::Clockwise : RotationDirection::CounterClockwise;
        a.rotationSpeedDegPerSecond = num(m, "rotationSpeedDegPerSecond", a.rotationSpeedDegPerSecond);
        a.mode = m.value(QStringLiteral("video")).toBool() ? PanoramaMode::Video : PanoramaMode::Photo;
        return a;
    }
    if (kind == QLatin1String("cameraControl")) {
        const auto optional = [&m](const char *key) -> std::optional<double> {
            const QVariant v = m.value(QLatin1String(key));
            bool ok = false;
            const double d = v.toDouble(&ok);
            return ok && !v.toString().isEmpty() ? std::optional<double>(d) : std::nullopt;
        };
        CameraControlAction a;
        a.tiltDeg = optional("tiltDeg");
        a.rollDeg = optional("rollDeg");
        a.yawDeg = optional("yawDeg");
        if (const auto zoom = optional("zoomLevel"))
            a.zoomLevel = int(*zoom);
        return a;
    }
    return std::nullopt;
}

namespace {
ActionField number(const char *name, const char *label, const char *unit, std::optional<double> minimum,
                   std::optional<double> maximum = std::nullopt, ActionField::Type type = ActionField::Type::Number)
{
    return {QString::fromLatin1(name), QCoreApplication::translate("ActionVariants", label), type,
            QString::fromUtf8(unit), minimum, maximum, {}, false};
}

ActionField optional(ActionField f)
{
    f.optional = true;
    return f;
}

ActionField toggle(const char *name, const char *label)
{
    return {QString::fromLatin1(name), QCoreApplication::translate("ActionVariants", label), ActionField::Type::Toggle, {}, {}, {}, {}, false};
}

ActionField choice(const char *name, const char *label, std::vector<std::pair<QString, QString>> choices)
{
    return {QString::fromLatin1(name), QCoreApplication::translate("ActionVariants", label), ActionField::Type::Choice, {}, {}, {},
            std::move(choices), false};
}

ActionKindDescription kind(const char *name, const char *label, std::vector<ActionField> fields)
{
    return {QString::fromLatin1(name), QCoreApplication::translate("ActionVariants", label), std::move(fields)};
}
} // namespace

namespace {
// The schema's description of a server action, in the editor's terms. Every field may be left unset:
// the server then applies its own default.
ActionKindDescription serverKindDescription(const ServerActionKind &k)
{
    ActionKindDescription d{k.kind, k.label, {}};
    for (const ServerActionField &f : k.fields) {
        ActionField field{f.name, f.label, ActionField::Type::Number, f.unit, f.minimum, f.maximum, f.choices, true};
        switch (f.type) {
        case ServerActionField::Type::Boolean: field.type = ActionField::Type::Toggle; field.optional = false; break;
        case ServerActionField::Type::Choice: field.type = ActionField::Type::Choice; field.optional = false; break;
        case ServerActionField::Type::Real: break;
        case ServerActionField::Type::Integer: field.type = ActionField::Type::Integer; break;
        }
        d.fields.push_back(std::move(field));
    }
    return d;
}
} // namespace

QString actionText(const QString &source)
{
    return source.isEmpty() ? source : QCoreApplication::translate("ActionVariants", source.toUtf8().constData());
}

QString ActionField::check(const QVariant &value) const
{
    const QString shownLabel = actionText(label), shownUnit = actionText(unit);
    switch (type) {
    case Type::Toggle:
        return value.canConvert<bool>() ? QString() : QCoreApplication::translate("ActionVariants", "%1 is either on or off").arg(shownLabel);
    case Type::Choice:
        for (const auto &c : choices)
            if (c.first == value.toString())
                return {};
        return QCoreApplication::translate("ActionVariants", "%1: \"%2\" is not one of its choices").arg(shownLabel, value.toString());
    case Type::Number:
    case Type::Integer: {
        if (optional && value.toString().trimmed().isEmpty())
            return {};  // not set
        bool ok = false;
        const double v = value.toString().trimmed().isEmpty() ? std::nan("") : value.toDouble(&ok);
        if (!ok || !std::isfinite(v))
            return QCoreApplication::translate("ActionVariants", "%1: \"%2\" is not a number").arg(shownLabel, value.toString());
        if (type == Type::Integer && std::floor(v) != v)
            return QCoreApplication::translate("ActionVariants", "%1: %2 is not a whole number").arg(shownLabel, value.toString());
        if (minimum && v < *minimum)
            return QCoreApplication::translate("ActionVariants", "%1: %2 is below %3 %4").arg(shownLabel, QString::number(v), QString::number(*minimum), shownUnit).trimmed();
        if (maximum && v > *maximum)
            return QCoreApplication::translate("ActionVariants", "%1: %2 is above %3 %4").arg(shownLabel, QString::number(v), QString::number(*maximum), shownUnit).trimmed();
        return {};
    }
    }
    return {};
}

const std::vector<ActionKindDescription> &editableActionKinds()
{
    using T = ActionField::Type;
    // Labels and units stay in English here (the source text): actionText() translates them when shown.
    static const std::vector<ActionKindDescription> kinds{
        kind("cameraTrigger", QT_TRANSLATE_NOOP("ActionVariants", "Camera"),
             {choice("state", QT_TRANSLATE_NOOP("ActionVariants", "Camera"),
                     {{"singleShot", QT_TRANSLATE_NOOP("ActionVariants", "Take a photo")},
                      {"startRecording", QT_TRANSLATE_NOOP("ActionVariants", "Start video")},
                      {"stopRecording", QT_TRANSLATE_NOOP("ActionVariants", "Stop video")},
                      {"toggleRecording", QT_TRANSLATE_NOOP("ActionVariants", "Toggle video")}})}),
        kind("cameraSeriesByDistance", QT_TRANSLATE_NOOP("ActionVariants", "Photos by distance"),
             {number("intervalMeters", QT_TRANSLATE_NOOP("ActionVariants", "Every"), QT_TRANSLATE_NOOP("ActionVariants", "m"), 0, 10000),
              number("shots", QT_TRANSLATE_NOOP("ActionVariants", "Shots (0: until stopped)"), "", 0, 100000, T::Integer),
              number("startDelaySeconds", QT_TRANSLATE_NOOP("ActionVariants", "Start after"), QT_TRANSLATE_NOOP("ActionVariants", "s"), 0, 3600)}),
        kind("cameraSeriesByTime", QT_TRANSLATE_NOOP("ActionVariants", "Photos by time"),
             {number("intervalSeconds", QT_TRANSLATE_NOOP("ActionVariants", "Every"), QT_TRANSLATE_NOOP("ActionVariants", "s"), 0.1, 3600),
              number("shots", QT_TRANSLATE_NOOP("ActionVariants", "Shots (0: until stopped)"), "", 0, 100000, T::Integer),
              number("startDelaySeconds", QT_TRANSLATE_NOOP("ActionVariants", "Start after"), QT_TRANSLATE_NOOP("ActionVariants", "s"), 0, 3600)}),
        kind("wait", QT_TRANSLATE_NOOP("ActionVariants", "Wait"),
             {number("seconds", QT_TRANSLATE_NOOP("ActionVariants", "For"), QT_TRANSLATE_NOOP("ActionVariants", "s"), 0, 86400),
              toggle("waitForOperator", QT_TRANSLATE_NOOP("ActionVariants", "Until the operator continues"))}),
        kind("heading", QT_TRANSLATE_NOOP("ActionVariants", "Heading"),
             {number("headingDeg", QT_TRANSLATE_NOOP("ActionVariants", "Heading"), "°", 0, 360),
              toggle("relativeToNextWaypoint", QT_TRANSLATE_NOOP("ActionVariants", "From the course"))}),
        kind("poi", QT_TRANSLATE_NOOP("ActionVariants", "Point of interest"),
             {number("latitude", QT_TRANSLATE_NOOP("ActionVariants", "Latitude"), "°", -90, 90),
              number("longitude", QT_TRANSLATE_NOOP("ActionVariants", "Longitude"), "°", -180, 180),
              number("altitude", QT_TRANSLATE_NOOP("ActionVariants", "Altitude"), QT_TRANSLATE_NOOP("ActionVariants", "m"), -500, 10000),
              choice("altitudeType", QT_TRANSLATE_NOOP("ActionVariants", "Altitude type"),
                     {{"AGL", QT_TRANSLATE_NOOP("ActionVariants", "Above ground (AGL)")},
                      {"AMSL", QT_TRANSLATE_NOOP("ActionVariants", "Above sea level (AMSL)")}})}),
        kind("cameraControl", QT_TRANSLATE_NOOP("ActionVariants", "Gimbal and zoom"),
             {optional(number("tiltDeg", QT_TRANSLATE_NOOP("ActionVariants", "Tilt (90: down)"), "°", -90, 180)),
              optional(number("rollDeg", QT_TRANSLATE_NOOP("ActionVariants", "Roll"), "°", -90, 90)),
              optional(number("yawDeg", QT_TRANSLATE_NOOP("ActionVariants", "Yaw"), "°", -360, 360)),
              optional(number("zoomLevel", QT_TRANSLATE_NOOP("ActionVariants", "Zoom level"), "", 0, 1000, T::Integer))}),
        kind("panorama", QT_TRANSLATE_NOOP("ActionVariants", "Panorama"),
             {number("angleDeg", QT_TRANSLATE_NOOP("ActionVariants", "Angle"), "°", 1, 360),
              number("stepAngleDeg", QT_TRANSLATE_NOOP("ActionVariants", "Step"), "°", 0, 360),
              number("stepDelaySeconds", QT_TRANSLATE_NOOP("ActionVariants", "Pause per step"), QT_TRANSLATE_NOOP("ActionVariants", "s"), 0, 600),
              number("rotationSpeedDegPerSecond", QT_TRANSLATE_NOOP("ActionVariants", "Rotation speed"), QT_TRANSLATE_NOOP("ActionVariants", "°/s"), 0.1, 360),
              toggle("clockwise", QT_TRANSLATE_NOOP("ActionVariants", "Clockwise")),
              toggle("video", QT_TRANSLATE_NOOP("ActionVariants", "Video"))}),
    };
    static const std::vector<ActionKindDescription> all = [] {
        std::vector<ActionKindDescription> list = kinds;
        for (const ServerActionKind &k : serverActionKinds())
            list.push_back(serverKindDescription(k));
        return list;
    }();
    return all;
}

const ActionKindDescription *actionKindDescription(const QString &name)
{
    for (const ActionKindDescription &k : editableActionKinds())
        if (k.kind == name)
            return &k;
    return nullptr;
}

} // namespace sortie::mission
