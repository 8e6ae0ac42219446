#pragma once

#include <QString>
#include <QStringView>

#include <optional>
#include <vector>

namespace sortie::mission {

// What a UgCS traverse algorithm is and which parameters it takes: the value form of the server's
// TraverseAlgorithm / ParameterDefinition objects (see AlgorithmProto.h), so that editors, validation
// and planning are built from a description rather than from code per algorithm.

// ParameterDefinition.type on the wire (PT_STRING=0 ... PT_SELECTION=4).
enum class ParameterType { String = 0, Integer = 1, Double = 2, Boolean = 3, Selection = 4 };

// What a number measures, which fixes its unit. The first values mirror the wire's PhysicalSemantic;
// Percent and Count have no wire semantic (a server sends PS_NONE for them).
enum class Quantity {
    None, Distance, Altitude, Speed, VerticalSpeed, Area, Gsd, Angle, Duration,
    Percent, Count
};
// The unit a quantity is written in on the wire: "m", "m/s", "m²", "cm/px", "°", "s", "%"; empty for None/Count.
QString unitSymbol(Quantity q);

// Where a figure's points come from (Figure.type on the wire, same numbers).
enum class FigureType { Point = 0, Polygon = 1, Circle = 2, EightCurve = 3, TakeoffPoint = 4, LandingPoint = 5, Polyline = 6 };

struct ParameterChoice
{
    QString value;        // on the wire, e.g. "STOP_AND_TURN"
    QString displayName;  // for the operator, e.g. "Stop and turn"
    bool operator==(const ParameterChoice &) const = default;
};

struct ParameterDefinition
{
    QString name;                 // the wire name, = ParameterValue.name
    QString displayName;          // for the operator; the name when the server gives none
    QString description;
    ParameterType type = ParameterType::String;
    Quantity quantity = Quantity::None;
    QString defaultValue;         // wire text; empty = no default (the parameter is "not set")
    std::optional<double> minimum, maximum;  // inclusive, for Integer/Double
    std::vector<ParameterChoice> choices;    // for Selection; empty = free text (e.g. a camera the server lists)
    bool mandatory = false;
    bool advanced = false;        // ParameterCategory PG_ADVANCED
    bool automatic = false;
    QString validationRegex;      // as the server gave it, empty when none

    QString unit() const { return unitSymbol(quantity); }
    // Why `value` is not acceptable for this parameter (type, range, choices, regex), or an empty string.
    // An empty value is acceptable unless the parameter is mandatory and has no default.
    QString check(const QString &value) const;
    bool operator==(const ParameterDefinition &) const = default;
};

// A parameter's value as the wire carries it: both strings, kept in the order received.
struct ParameterValue
{
    QString name;
    QString value;
    bool operator==(const ParameterValue &) const = default;
};
using ParameterValues = std::vector<ParameterValue>;

// Wire text parsing, tolerant the way UgCS peers write: "5", "5.0", " 5 "; booleans in any case.
std::optional<double> parseParameterNumber(const QString &text);
std::optional<bool> parseParameterBoolean(const QString &text);
// Shortest text that reads back to the same double ("5", "2.5", "0.1").
QString parameterNumberText(double v);

// The tools UgCS has. Unknown = an algorithm this build has no planner or built-in entry for.
enum class AlgorithmKind {
    Unknown, Waypoint, TakeOff, Landing, Circle, Perimeter, AreaScan, Photogrammetry, Corridor,
    ExpandingSquare, CreepingLine, FacadeScanner
};

struct AlgorithmDefinition
{
    QString className;            // TraverseAlgorithm.implementationClass = SegmentDefinition.algorithmClassName
    QString displayName;          // TraverseAlgorithm.name
    QString code;                 // TraverseAlgorithm.code, when the server gives one
    AlgorithmKind kind = AlgorithmKind::Unknown;
    FigureType figure = FigureType::Point;
    int minimumPoints = 1;        // distinct figure points the tool needs (a polygon 3, a polyline 2)
    std::vector<ParameterDefinition> parameters;
    int serverId = 0;             // TraverseAlgorithm.id on the server it came from, 0 when built in

    const ParameterDefinition *parameter(QStringView name) const;
    bool operator==(const AlgorithmDefinition &) const = default;
};

// The class name prefix every UgCS algorithm carries.
inline constexpr const char *kUgcsAlgorithmPackage = "com.ugcs.ucs.service.routing.impl.";

// Typed reading of a segment's values against its definition: a value that is missing, empty or
// unreadable gives the definition's default; a name the definition lacks reads as missing.
class ParameterReader
{
public:
    ParameterReader(const AlgorithmDefinition &algorithm, const ParameterValues &values)
        : m_algorithm(algorithm), m_values(values) {}

    // The raw text sent for `name`, or nullopt when the segment does not carry it.
    std::optional<QString> text(QStringView name) const;
    // The value, else the default; nullopt when neither is set (e.g. overshoot "").
    std::optional<double> number(QStringView name) const;
    std::optional<bool> boolean(QStringView name) const;
    QString selection(QStringView name) const;  // the value, else the default, else empty
    double number(QStringView name, double fallback) const { return number(name).value_or(fallback); }
    bool boolean(QStringView name, bool fallback) const { return boolean(name).value_or(fallback); }

    // One message per value out of its definition's range, type or choices, each naming the parameter
    // ("overlapForward: 95 is above the maximum of 90 %").
    std::vector<QString> problems() const;

private:
    std::optional<QString> effective(QStringView name) const;
    const AlgorithmDefinition &m_algorithm;
    const ParameterValues &m_values;
};

} // namespace sortie::mission
