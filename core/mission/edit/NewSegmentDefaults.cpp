// The first values of a segment the operator adds: heights, speeds and parameters from the route.
#include "NewSegmentDefaults.h"

#include "Camera.h"
#include "SegmentParameters.h"

#include <algorithm>

namespace sortie::mission {

double newFigureHeight(const RouteSettings &settings)
{
    return std::max(settings.safeAltitude, std::min(50.0, settings.maxAltitude));
}

Waypoint newWaypoint(const RouteSettings &settings, const Waypoint *previousPass, const GeoPoint &position)
{
    Waypoint w;
    w.altitude = newFigureHeight(settings);
    w.speed = settings.initialSpeed;
    if (previousPass) {
        w.altitude = previousPass->altitude;
        w.altitudeType = previousPass->altitudeType;
        w.speed = previousPass->speed;
        w.turnType = previousPass->turnType;
    }
    w.position = position;
    return w;
}

void applyAreaScanDefaults(AreaScan &scan, const RouteSettings &settings)
{
    scan.parameters.altitude = std::max(settings.safeAltitude, std::min(60.0, settings.maxAltitude));
    scan.parameters.speed = settings.initialSpeed;
    syncDerivedFields(scan.parameters);
}

void applyToolDefaults(AlgorithmSegment &a, const AlgorithmDefinition &def, const RouteSettings &settings)
{
    const double height = newFigureHeight(settings);
    if (def.figure == FigureType::Point || def.figure == FigureType::Circle)
        for (FigurePoint &p : a.points)
            p.altitude = height;  // the point tools fly at their point's altitude
    if (def.figure == FigureType::Circle)
        a.figureParameters = {50.0};
    for (const ParameterDefinition &p : def.parameters) {
        QString value = p.defaultValue;
        if (p.name == QLatin1String("height"))
            value = parameterNumberText(height);
        else if (p.name == QLatin1String("camera") && value.isEmpty() && !builtInCameras().empty())
            value = builtInCameras().front().name;  // a photo tool flies with a camera from the start
        else if (p.name == QLatin1String("speed"))
            value = parameterNumberText(settings.initialSpeed);
        if (!value.isEmpty())
            a.parameters.push_back({p.name, value});
    }
}

} // namespace sortie::mission
