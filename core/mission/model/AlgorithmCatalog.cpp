#include "AlgorithmCatalog.h"

#include <array>
#include <cstring>

namespace sortie::mission {

namespace {

struct KindName { AlgorithmKind kind; const char *shortName; };
// Class names: the first seven are UgCS's own (facts §2); the last four were not found in public
// sources and are Sortie's choice, documented in docs/missions.md.
constexpr std::array<KindName, 11> kKindNames{{
    {AlgorithmKind::Waypoint, "WaypointAlgorithm"},
    {AlgorithmKind::TakeOff, "TakeOffAlgorithm"},
    {AlgorithmKind::Landing, "LandingAlgorithm"},
    {AlgorithmKind::Circle, "CircleAlgorithm"},
    {AlgorithmKind::Perimeter, "PerimeterAlgorithm"},
    {AlgorithmKind::AreaScan, "AreaScanAlgorithm"},
    {AlgorithmKind::Photogrammetry, "PhotogrammetryAlgorithm"},
    {AlgorithmKind::Corridor, "CorridorMappingAlgorithm"},
    {AlgorithmKind::ExpandingSquare, "ExpandingSquareAlgorithm"},
    {AlgorithmKind::CreepingLine, "CreepingLineAlgorithm"},
    {AlgorithmKind::FacadeScanner, "FacadeScannerAlgorithm"},
}};

// Builders for the parameter table: one line per parameter below.
ParameterDefinition number(const char *name, const char *display, Quantity q, const char *def,
                           std::optional<double> min = std::nullopt, std::optional<double> max = std::nullopt)
{
    ParameterDefinition p;
    p.name = QString::fromLatin1(name);
    p.displayName = QString::fromUtf8(display);
    p.type = ParameterType::Double;
    p.quantity = q;
    p.defaultValue = QString::fromLatin1(def);
    p.minimum = min;
    p.maximum = max;
    p.advanced = false;
    return p;
}

ParameterDefinition integer(const char *name, const char *display, Quantity q, const char *def,
                            std::optional<double> min = std::nullopt, std::optional<double> max = std::nullopt)
{
    ParameterDefinition p = number(name, display, q, def, min, max);
    p.type = ParameterType::Integer;
    return p;
}

ParameterDefinition boolean(const char *name, const char *display, bool def)
{
    ParameterDefinition p;
    p.name = QString::fromLatin1(name);
    p.displayName = QString::fromUtf8(display);
    p.type = ParameterType::Boolean;
    p.defaultValue = def ? QStringLiteral("true") : QStringLiteral("false");
    return p;
}

ParameterDefinition selection(const char *name, const char *display, const char *def,
                              std::initializer_list<std::pair<const char *, const char *>> choices)
{
    ParameterDefinition p;
    p.name = QString::fromLatin1(name);
    p.displayName = QString::fromUtf8(display);
    p.type = ParameterType::Selection;
    p.defaultValue = QString::fromLatin1(def);
    for (const auto &[value, label] : choices)
        p.choices.push_back({QString::fromLatin1(value), QString::fromUtf8(label)});
    return p;
}

ParameterDefinition advanced(ParameterDefinition p)
{
    p.advanced = true;
    return p;
}

// The common parameters (facts §2.1), with their defaults where the facts give one.
ParameterDefinition speed() { return number("speed", "Speed", Quantity::Speed, "", 0.1); }
ParameterDefinition turnType()
{
    return selection("wpTurnType", "Turn type", "STOP_AND_TURN",
                     {{"STOP_AND_TURN", "Stop and turn"}, {"STRAIGHT", "Straight"}, {"SPLINE", "Spline"}, {"BANK_TURN", "Bank turn"}});
}
ParameterDefinition avoidObstacles() { return advanced(boolean("avoidObstacles", "Avoid obstacles", true)); }
ParameterDefinition avoidTerrain() { return advanced(boolean("avoidTerrain", "Avoid terrain", true)); }
ParameterDefinition altitudeType(const char *def)
{
    return selection("altitudeType", "Altitude type", def, {{"AGL", "Above ground (AGL)"}, {"AMSL", "Above sea level (AMSL)"}, {"WGS84", "WGS-84 ellipsoid"}});
}
ParameterDefinition actionExecution(bool forwardPasses)
{
    if (forwardPasses)
        return selection("actionExecution", "Action execution", "ACTIONS_EVERY_POINT",
                         {{"ONLY_AT_START", "Only at start"}, {"ACTIONS_EVERY_POINT", "At every point"}, {"ACTIONS_ON_FORWARD_PASSES", "On forward passes"}});
    return selection("actionExecution", "Action execution", "ACTIONS_EVERY_POINT",
                     {{"ONLY_AT_START", "Only at start"}, {"ACTIONS_EVERY_POINT", "At every point"}});
}
ParameterDefinition noActionsAtLastPoint() { return advanced(boolean("noActionsAtLastPoint", "No actions at last point", true)); }
ParameterDefinition tolerance() { return advanced(number("tolerance", "AGL tolerance", Quantity::Distance, "3", 0)); }
ParameterDefinition allowPartial() { return advanced(boolean("areaScanAllowPartialCalculation", "Allow partial calculation", false)); }
ParameterDefinition overshoot() { return advanced(number("overshoot", "Overshoot", Quantity::Distance, "", 0, 1000)); }
ParameterDefinition overshootSpeed() { return advanced(number("overshootSpeed", "Overshoot speed", Quantity::Speed, "", 0.1)); }
ParameterDefinition directionAngle() { return number("directionAngle", "Direction angle", Quantity::Angle, "0", 0, 360); }
ParameterDefinition doubleGrid() { return advanced(boolean("doubleGrid", "Double grid", false)); }
ParameterDefinition camera()
{
    ParameterDefinition p;
    p.name = QStringLiteral("camera");
    p.displayName = QStringLiteral("Camera");
    p.description = QStringLiteral("A camera payload of the route's vehicle profile, by id or name");
    p.type = ParameterType::Selection;  // choices come from the server's profile (GetParametersSelectionValues)
    return p;
}
ParameterDefinition gsd(const char *def) { return number("groundSampleDistance", "Ground sample distance", Quantity::Gsd, def, 0.05, 1000); }
ParameterDefinition overlapForward(const char *def) { return number("overlapForward", "Forward overlap", Quantity::Percent, def, 1, 90); }
ParameterDefinition overlapSide(const char *def, double max = 90) { return number("overlapSide", "Side overlap", Quantity::Percent, def, 1, max); }
ParameterDefinition camTopFacingForward() { return boolean("camTopFacingForward", "Camera top facing forward", true); }
ParameterDefinition height(const char *display, const char *def) { return number("height", display, Quantity::Altitude, def, 0, 10000); }

AlgorithmDefinition algorithm(AlgorithmKind kind, const char *display, FigureType figure, int minPoints,
                              std::vector<ParameterDefinition> parameters)
{
    AlgorithmDefinition a;
    a.className = algorithmClassName(kind);
    a.code = a.className.section(QLatin1Char('.'), -1).chopped(int(std::strlen("Algorithm")));  // "Circle", "AreaScan"
    a.displayName = QString::fromUtf8(display);
    a.kind = kind;
    a.figure = figure;
    a.minimumPoints = minPoints;
    a.parameters = std::move(parameters);
    return a;
}

std::vector<AlgorithmDefinition> builtInDefinitions()
{
    std::vector<AlgorithmDefinition> all;
    all.push_back(algorithm(AlgorithmKind::Waypoint, "Waypoint", FigureType::Point, 1, {
        speed(), turnType(), avoidObstacles(), avoidTerrain(), altitudeType("AGL"),
        advanced(number("cornerRadius", "Corner radius", Quantity::Distance, "", 0)),
    }));
    all.push_back(algorithm(AlgorithmKind::TakeOff, "Take-off", FigureType::TakeoffPoint, 1, {
        speed(), avoidObstacles(), avoidTerrain(),
    }));
    all.push_back(algorithm(AlgorithmKind::Landing, "Landing", FigureType::LandingPoint, 1, {
        avoidObstacles(), avoidTerrain(),
    }));
    all.push_back(algorithm(AlgorithmKind::Circle, "Circle", FigureType::Circle, 1, {
        speed(), turnType(),
        integer("loops", "Loops", Quantity::Count, "1", 1, 100),
        boolean("flightClockwise", "Clockwise", true),
        advanced(integer("basePointsQnt", "Points per loop", Quantity::Count, "", 3, 360)),
        advanced(boolean("followTerrain", "Follow terrain", true)),
        actionExecution(false), avoidObstacles(), avoidTerrain(), noActionsAtLastPoint(),
    }));
    all.push_back(algorithm(AlgorithmKind::Perimeter, "Perimeter", FigureType::Polygon, 3, {
        speed(), turnType(), height("Height", "50"),
        boolean("heightAgl", "Height above ground", true),
        integer("loops", "Loops", Quantity::Count, "1", 1, 100),
        actionExecution(false), avoidObstacles(), avoidTerrain(), noActionsAtLastPoint(),
    }));
    all.push_back(algorithm(AlgorithmKind::AreaScan, "Area scan", FigureType::Polygon, 3, {
        speed(), turnType(), height("Height", "50"), altitudeType("AMSL"),
        number("sideDistance", "Side distance", Quantity::Distance, "20", 0.5, 10000),
        directionAngle(), avoidObstacles(), actionExecution(true), overshoot(), overshootSpeed(),
        allowPartial(), tolerance(), noActionsAtLastPoint(), doubleGrid(),
    }));
    all.push_back(algorithm(AlgorithmKind::Photogrammetry, "Photogrammetry", FigureType::Polygon, 3, {
        speed(), turnType(), camera(), gsd("2"), overlapForward("60"), overlapSide("30"), camTopFacingForward(),
        directionAngle(), avoidObstacles(), actionExecution(true),
        advanced(boolean("generateAdditionalWaypoints", "Additional waypoints", false)),
        overshoot(), overshootSpeed(), altitudeType("AMSL"), allowPartial(), tolerance(), noActionsAtLastPoint(), doubleGrid(),
    }));
    // Wire names not found in public sources: Sortie's, matching photogrammetry's where the field is the same.
    all.push_back(algorithm(AlgorithmKind::Corridor, "Corridor mapping", FigureType::Polyline, 2, {
        speed(), turnType(), number("width", "Width", Quantity::Distance, "30", 1, 10000),
        camera(), gsd("2"), overlapForward("60"), overlapSide("30"), camTopFacingForward(),
        tolerance(), avoidObstacles(), altitudeType("AMSL"), actionExecution(true), noActionsAtLastPoint(),
    }));
    all.push_back(algorithm(AlgorithmKind::ExpandingSquare, "Expanding square", FigureType::Point, 1, {
        height("Height (AGL)", "50"), speed(), turnType(), camera(), tolerance(),
        number("searchRadius", "Search radius", Quantity::Distance, "350", 1, 100000),
        directionAngle(), overlapSide("10"), avoidObstacles(), actionExecution(false), noActionsAtLastPoint(),
    }));
    all.push_back(algorithm(AlgorithmKind::CreepingLine, "Creeping line", FigureType::Polygon, 3, {
        speed(), turnType(), camera(), height("Height (AGL)", "50"), tolerance(), directionAngle(),
        overlapSide("10", 50), avoidObstacles(), actionExecution(false), noActionsAtLastPoint(),
    }));
    all.push_back(algorithm(AlgorithmKind::FacadeScanner, "Facade scanner", FigureType::Polyline, 2, {
        number("minHeight", "Minimum height (AGL)", Quantity::Altitude, "10", 0, 10000),
        number("maxHeight", "Maximum height (AGL)", Quantity::Altitude, "40", 0, 10000),
        number("distanceToFacade", "Distance to facade", Quantity::Distance, "20", 1, 1000),
        camera(), overlapForward("60"), overlapSide("60"),
        selection("facadeScanPattern", "Pattern", "VERTICAL", {{"VERTICAL", "Vertical"}, {"HORIZONTAL", "Horizontal"}}),
        number("verticalSpeed", "Vertical speed", Quantity::VerticalSpeed, "", 0.1),
        number("horizontalSpeed", "Horizontal speed", Quantity::Speed, "", 0.1),
        actionExecution(true),
    }));
    return all;
}

} // namespace

QString algorithmClassName(AlgorithmKind kind)
{
    for (const KindName &k : kKindNames)
        if (k.kind == kind)
            return QLatin1String(kUgcsAlgorithmPackage) + QLatin1String(k.shortName);
    return {};
}

AlgorithmKind algorithmKindOf(QStringView className)
{
    const QLatin1String package(kUgcsAlgorithmPackage);
    const QStringView shortName = className.startsWith(package) ? className.mid(package.size()) : className;
    for (const KindName &k : kKindNames)
        if (shortName == QLatin1String(k.shortName))
            return k.kind;
    return AlgorithmKind::Unknown;
}

const AlgorithmCatalog &AlgorithmCatalog::builtIn()
{
    static const AlgorithmCatalog catalog(builtInDefinitions());
    return catalog;
}

const AlgorithmDefinition *AlgorithmCatalog::byClassName(QStringView className) const
{
    for (const AlgorithmDefinition &a : m_algorithms)
        if (a.className == className)
            return &a;
    return nullptr;
}

const AlgorithmDefinition *AlgorithmCatalog::byKind(AlgorithmKind kind) const
{
    for (const AlgorithmDefinition &a : m_algorithms)
        if (a.kind == kind)
            return &a;
    return nullptr;
}

void AlgorithmCatalog::insert(AlgorithmDefinition definition)
{
    for (AlgorithmDefinition &a : m_algorithms) {
        if (a.className == definition.className) {
            a = std::move(definition);
            return;
        }
    }
    m_algorithms.push_back(std::move(definition));
}

} // namespace sortie::mission
