#include "SegmentParameters.h"

#include "Camera.h"

#include <cmath>
#include <QCoreApplication>

namespace sortie::mission {

namespace {

std::optional<double> toNumber(const QVariant &v)
{
    if (v.metaType().id() == QMetaType::QString) {
        bool ok = false;
        const double d = v.toString().trimmed().toDouble(&ok);
        return ok && std::isfinite(d) ? std::optional(d) : std::nullopt;
    }
    if (v.metaType().id() == QMetaType::Bool || !v.canConvert<double>())
        return std::nullopt;
    bool ok = false;
    const double d = v.toDouble(&ok);
    return ok && std::isfinite(d) ? std::optional(d) : std::nullopt;
}

// Selections arrive as their wire name or as the enum itself (from QML).
// QML hands an enum over as its number.
std::optional<int> enumNumber(const QVariant &v, int count)
{
    const int id = v.metaType().id();
    if (id != QMetaType::Int && id != QMetaType::Double && id != QMetaType::LongLong)
        return std::nullopt;
    const double d = v.toDouble();
    return d >= 0 && d < count && d == std::floor(d) ? std::optional(int(d)) : std::nullopt;
}

std::optional<AltitudeType> toAltitudeType(const QVariant &v)
{
    if (v.metaType() == QMetaType::fromType<AltitudeType>())
        return v.value<AltitudeType>();
    if (const auto n = enumNumber(v, 2))
        return AltitudeType(*n);
    const QString t = v.toString().trimmed();
    if (t.compare(QLatin1String("AGL"), Qt::CaseInsensitive) == 0)
        return AltitudeType::Agl;
    if (t.compare(QLatin1String("AMSL"), Qt::CaseInsensitive) == 0 || t.compare(QLatin1String("WGS84"), Qt::CaseInsensitive) == 0)
        return AltitudeType::Amsl;
    return std::nullopt;
}

const char *wireTurnName(TurnType t)
{
    switch (t) {
    case TurnType::StopAndTurn: return "STOP_AND_TURN";
    case TurnType::Straight: return "STRAIGHT";
    case TurnType::Spline: return "SPLINE";
    case TurnType::BankTurn: return "BANK_TURN";
    }
    return "STOP_AND_TURN";
}

std::optional<TurnType> toTurnType(const QVariant &v)
{
    if (v.metaType() == QMetaType::fromType<TurnType>())
        return v.value<TurnType>();
    if (const auto n = enumNumber(v, 4))
        return TurnType(*n);
    const QString t = v.toString().trimmed();
    for (TurnType tt : {TurnType::StopAndTurn, TurnType::Straight, TurnType::Spline, TurnType::BankTurn})
        if (t.compare(QLatin1String(wireTurnName(tt)), Qt::CaseInsensitive) == 0 || t.compare(turnTypeName(tt), Qt::CaseInsensitive) == 0)
            return tt;
    return std::nullopt;
}

bool fail(QString *error, const QString &text)
{
    if (error)
        *error = text;
    return false;
}

// A number in [min, max] (open at the top when maxOpen), written through `apply`.
template<typename Apply>
bool number(const QVariant &value, const QString &name, double min, double max, bool maxOpen, QString *error, Apply apply)
{
    const auto d = toNumber(value);
    if (!d)
        return fail(error, QCoreApplication::translate("SegmentParameters", "%1 needs a number, not \"%2\".").arg(name, value.toString()));
    if (*d < min || *d > max || (maxOpen && *d == max))
        return fail(error, (maxOpen ? QCoreApplication::translate("SegmentParameters", "%1 must be from %2 to below %3.")
                                    : QCoreApplication::translate("SegmentParameters", "%1 must be from %2 to %3."))
                               .arg(name).arg(min).arg(max));
    apply(*d);
    return true;
}

constexpr double kHuge = 1e7;

bool setScan(AreaScanParameters &p, const QString &name, const QVariant &value, QString *error)
{
    if (name == QLatin1String("height"))
        return number(value, name, 0.1, 1e5, false, error, [&](double d) {
            p.heightMode = ScanHeightMode::Altitude;
            p.altitude = d;
        });
    if (name == QLatin1String("groundSampleDistance"))  // cm/px
        return number(value, name, 0.01, 1e4, false, error, [&](double d) {
            p.heightMode = ScanHeightMode::GroundSampleDistance;
            p.groundSampleDistanceCm = d;
        });
    if (name == QLatin1String("altitudeType")) {
        const auto t = toAltitudeType(value);
        if (!t)
            return fail(error, QCoreApplication::translate("SegmentParameters", "altitudeType is AGL or AMSL, not \"%1\".").arg(value.toString()));
        p.altitudeType = *t;
        return true;
    }
    if (name == QLatin1String("overlapForward"))
        return number(value, name, 0, 100, true, error, [&](double d) { p.frontOverlapPercent = d; });
    if (name == QLatin1String("overlapSide"))
        return number(value, name, 0, 100, true, error, [&](double d) { p.sideOverlapPercent = d; });
    if (name == QLatin1String("sideDistance"))  // 0 = from the camera and the side overlap
        return number(value, name, 0, kHuge, false, error, [&](double d) { p.sideDistanceMeters = d; });
    if (name == QLatin1String("directionAngle"))
        return number(value, name, -360, 360, false, error, [&](double d) { p.directionDeg = std::fmod(d + 360.0, 360.0); });
    if (name == QLatin1String("overshoot"))
        return number(value, name, 0, kHuge, false, error, [&](double d) { p.turnaroundMeters = d; });
    if (name == QLatin1String("speed"))
        return number(value, name, 0.1, 1000, false, error, [&](double d) { p.speed = d; });
    if (name == QLatin1String("tolerance")) {
        if (!value.isValid() || value.toString().trimmed().isEmpty()) {
            p.toleranceMeters.reset();  // the server's own
            return true;
        }
        return number(value, name, 0, kHuge, false, error, [&](double d) { p.toleranceMeters = d; });
    }
    if (name == QLatin1String("camera")) {
        // A camera Sortie knows brings its optics; another name only names the optics there are.
        const QString n = value.toString();
        if (n.isEmpty())
            return fail(error, QCoreApplication::translate("SegmentParameters", "camera needs a name."));
        if (const auto known = builtInCamera(n))
            p.camera = *known;
        else
            p.camera.name = n;
        return true;
    }
    // A custom camera's optics, Sortie's own names (docs/missions.md): millimetres and pixels.
    if (name == QLatin1String("cameraSensorWidth"))
        return number(value, name, 0.01, 1000, false, error, [&](double d) { p.camera.sensorWidthMm = d; });
    if (name == QLatin1String("cameraSensorHeight"))
        return number(value, name, 0.01, 1000, false, error, [&](double d) { p.camera.sensorHeightMm = d; });
    if (name == QLatin1String("cameraFocalLength"))
        return number(value, name, 0.01, 10000, false, error, [&](double d) { p.camera.focalLengthMm = d; });
    if (name == QLatin1String("cameraImageWidth"))
        return number(value, name, 1, 1e6, false, error, [&](double d) { p.camera.imageWidthPx = int(d); });
    if (name == QLatin1String("cameraImageHeight"))
        return number(value, name, 1, 1e6, false, error, [&](double d) { p.camera.imageHeightPx = int(d); });
    return fail(error, QCoreApplication::translate("SegmentParameters", "An area scan has no parameter \"%1\".").arg(name));
}

QVariant scanValue(const AreaScanParameters &p, const QString &name)
{
    if (name == QLatin1String("height")) return scanAltitude(p);
    if (name == QLatin1String("groundSampleDistance")) return scanGroundSampleDistanceCm(p);
    if (name == QLatin1String("altitudeType")) return altitudeTypeName(p.altitudeType);
    if (name == QLatin1String("overlapForward")) return p.frontOverlapPercent;
    if (name == QLatin1String("overlapSide")) return p.sideOverlapPercent;
    if (name == QLatin1String("sideDistance")) return p.sideDistanceMeters;
    if (name == QLatin1String("directionAngle")) return p.directionDeg;
    if (name == QLatin1String("overshoot")) return p.turnaroundMeters;
    if (name == QLatin1String("speed")) return p.speed;
    if (name == QLatin1String("tolerance")) return p.toleranceMeters ? QVariant(*p.toleranceMeters) : QVariant();
    if (name == QLatin1String("camera")) return p.camera.name;
    if (name == QLatin1String("cameraSensorWidth")) return p.camera.sensorWidthMm;
    if (name == QLatin1String("cameraSensorHeight")) return p.camera.sensorHeightMm;
    if (name == QLatin1String("cameraFocalLength")) return p.camera.focalLengthMm;
    if (name == QLatin1String("cameraImageWidth")) return p.camera.imageWidthPx;
    if (name == QLatin1String("cameraImageHeight")) return p.camera.imageHeightPx;
    return {};
}

bool setWaypoint(Waypoint &w, const QString &name, const QVariant &value, QString *error)
{
    if (name == QLatin1String("speed"))
        return number(value, name, 0.1, 1000, false, error, [&](double d) { w.speed = d; });
    if (name == QLatin1String("wpTurnType")) {
        const auto t = toTurnType(value);
        if (!t)
            return fail(error, QCoreApplication::translate("SegmentParameters", "wpTurnType is STOP_AND_TURN, STRAIGHT, SPLINE or BANK_TURN, not \"%1\".").arg(value.toString()));
        w.turnType = *t;
        return true;
    }
    if (name == QLatin1String("altitudeType")) {
        const auto t = toAltitudeType(value);
        if (!t)
            return fail(error, QCoreApplication::translate("SegmentParameters", "altitudeType is AGL or AMSL, not \"%1\".").arg(value.toString()));
        w.altitudeType = *t;
        return true;
    }
    if (name == QLatin1String("acceptanceRadius"))
        return number(value, name, 0, kHuge, false, error, [&](double d) { w.acceptanceRadius = d; });
    return fail(error, QCoreApplication::translate("SegmentParameters", "A waypoint has no parameter \"%1\".").arg(name));
}

QVariant waypointValue(const Waypoint &w, const QString &name)
{
    if (name == QLatin1String("speed")) return w.speed;
    if (name == QLatin1String("wpTurnType")) return QString::fromLatin1(wireTurnName(w.turnType));
    if (name == QLatin1String("altitudeType")) return altitudeTypeName(w.altitudeType);
    if (name == QLatin1String("acceptanceRadius")) return w.acceptanceRadius;
    return {};
}

// The wire text of a typed value: numbers the shortest way, booleans as "true"/"false".
std::optional<QString> wireText(const QVariant &v)
{
    switch (v.metaType().id()) {
    case QMetaType::Bool: return v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    case QMetaType::Int: case QMetaType::LongLong: case QMetaType::UInt: case QMetaType::ULongLong:
    case QMetaType::Double: case QMetaType::Float: {
        const double d = v.toDouble();
        return std::isfinite(d) ? std::optional(parameterNumberText(d)) : std::nullopt;
    }
    case QMetaType::QString: return v.toString();
    default: return v.canConvert<QString>() ? std::optional(v.toString()) : std::nullopt;
    }
}

QVariant typedValue(const ParameterDefinition *def, const QString &text)
{
    if (!def)
        return text;
    switch (def->type) {
    case ParameterType::Integer:
    case ParameterType::Double:
        if (const auto d = parseParameterNumber(text))
            return *d;
        return text;  // shown as sent, flagged by validation
    case ParameterType::Boolean:
        if (const auto b = parseParameterBoolean(text))
            return *b;
        return text;
    default: return text;
    }
}

} // namespace

QStringList parameterNames(const Segment &segment, const AlgorithmCatalog &catalog)
{
    if (isWaypoint(segment))
        return {QStringLiteral("speed"), QStringLiteral("wpTurnType"), QStringLiteral("altitudeType"), QStringLiteral("acceptanceRadius")};
    if (const AlgorithmSegment *a = asAlgorithmSegment(segment)) {
        QStringList names;
        if (const AlgorithmDefinition *def = catalog.byClassName(a->algorithm))
            for (const ParameterDefinition &p : def->parameters)
                names << p.name;
        for (const ParameterValue &v : a->parameters)
            if (!names.contains(v.name))
                names << v.name;
        return names;
    }
    return {QStringLiteral("height"), QStringLiteral("groundSampleDistance"), QStringLiteral("altitudeType"),
            QStringLiteral("overlapForward"), QStringLiteral("overlapSide"), QStringLiteral("sideDistance"),
            QStringLiteral("directionAngle"), QStringLiteral("overshoot"), QStringLiteral("speed"), QStringLiteral("tolerance"),
            QStringLiteral("camera"),
            QStringLiteral("cameraSensorWidth"), QStringLiteral("cameraSensorHeight"), QStringLiteral("cameraFocalLength"),
            QStringLiteral("cameraImageWidth"), QStringLiteral("cameraImageHeight")};
}

QVariant parameterValue(const Segment &segment, const QString &name, const AlgorithmCatalog &catalog)
{
    if (const Waypoint *w = asWaypoint(segment))
        return waypointValue(*w, name);
    if (const AlgorithmSegment *a = asAlgorithmSegment(segment)) {
        const QString *text = a->value(name);
        if (!text || text->isEmpty())
            return {};
        const AlgorithmDefinition *def = catalog.byClassName(a->algorithm);
        return typedValue(def ? def->parameter(name) : nullptr, *text);
    }
    return scanValue(std::get<AreaScan>(segment).parameters, name);
}

bool setParameterValue(Segment &segment, const QString &name, const QVariant &value, QString *error, const AlgorithmCatalog &catalog)
{
    if (Waypoint *w = asWaypoint(segment)) {
        Waypoint copy = *w;
        if (!setWaypoint(copy, name, value, error))
            return false;
        *w = std::move(copy);
        return true;
    }
    if (AlgorithmSegment *a = asAlgorithmSegment(segment)) {
        const AlgorithmDefinition *def = catalog.byClassName(a->algorithm);
        const ParameterDefinition *p = def ? def->parameter(name) : nullptr;
        if (!p && !a->value(name))
            return fail(error, QCoreApplication::translate("SegmentParameters", "%1 has no parameter \"%2\".").arg(algorithmLabel(*a), name));
        std::optional<QString> text = wireText(value);
        if (p && p->type == ParameterType::Selection && value.metaType() == QMetaType::fromType<AltitudeType>())
            text = altitudeTypeName(value.value<AltitudeType>());
        if (!text)
            return fail(error, QCoreApplication::translate("SegmentParameters", "%1 cannot take that value.").arg(name));
        if (p) {
            if (p->type == ParameterType::Boolean && value.metaType().id() != QMetaType::Bool && !parseParameterBoolean(*text)
                && !text->isEmpty())
                return fail(error, QCoreApplication::translate("SegmentParameters", "%1 is true or false, not \"%2\".").arg(name, *text));
            if (const QString problem = p->check(*text); !problem.isEmpty())
                return fail(error, problem);
        }
        a->setValue(name, *text);
        return true;
    }
    AreaScanParameters p = std::get<AreaScan>(segment).parameters;
    if (!setScan(p, name, value, error))
        return false;
    syncDerivedFields(p);
    std::get<AreaScan>(segment).parameters = p;
    return true;
}

} // namespace sortie::mission
