#include "Photogrammetry.h"

#include <algorithm>
#include <cmath>

namespace sortie::mission::photogrammetry {

double gsdAtHeight(const Camera &c, double height)
{
    if (!c.isValid())
        return 0.0;
    return height * c.sensorWidthMm / (c.focalLengthMm * c.imageWidthPx) * 100.0;
}

double heightForGsd(const Camera &c, double gsdCm)
{
    if (!c.isValid())
        return 0.0;
    return gsdCm / 100.0 * c.focalLengthMm * c.imageWidthPx / c.sensorWidthMm;
}

Footprint footprint(const Camera &c, double height, bool topForward)
{
    if (!c.isValid())
        return {};
    const double w = height * c.sensorWidthMm / c.focalLengthMm;
    const double h = height * c.sensorHeightMm / c.focalLengthMm;
    return topForward ? Footprint{w, h} : Footprint{h, w};
}

double passSpacing(double footprintAcross, double overlapSidePercent)
{
    return footprintAcross * (1.0 - overlapSidePercent / 100.0);
}

double triggerDistance(double footprintAlong, double overlapForwardPercent)
{
    return footprintAlong * (1.0 - overlapForwardPercent / 100.0);
}

double overlapFor(double spacing, double footprintLength)
{
    return footprintLength > 0 ? (1.0 - spacing / footprintLength) * 100.0 : 0.0;
}

int photosOnPass(double length, double trigger)
{
    if (!(trigger > 0) || !(length >= 0))
        return 1;
    return int(std::floor(length / trigger + 1e-9)) + 1;
}

double triggerInterval(double trigger, double speed, const Camera &c)
{
    const double t = speed > 0 ? trigger / speed : 0.0;
    return std::max(t, c.minTriggerIntervalS);
}

double maxSpeedForTrigger(double trigger, const Camera &c)
{
    return c.minTriggerIntervalS > 0 ? trigger / c.minTriggerIntervalS : 0.0;
}

Figures figuresForHeight(const Camera &c, double height, double overlapForward, double overlapSide, bool topForward,
                         double speed)
{
    Figures f;
    f.height = height;
    f.gsdCm = gsdAtHeight(c, height);
    f.footprint = footprint(c, height, topForward);
    f.passSpacing = passSpacing(f.footprint.across, overlapSide);
    f.triggerDistance = triggerDistance(f.footprint.along, overlapForward);
    f.triggerIntervalS = triggerInterval(f.triggerDistance, speed, c);
    f.maxSpeed = maxSpeedForTrigger(f.triggerDistance, c);
    return f;
}

Figures figuresForGsd(const Camera &c, double gsdCm, double overlapForward, double overlapSide, bool topForward,
                      double speed)
{
    Figures f = figuresForHeight(c, heightForGsd(c, gsdCm), overlapForward, overlapSide, topForward, speed);
    f.gsdCm = c.isValid() ? gsdCm : 0.0;
    return f;
}

int estimatedPhotos(double area, double spacing, double trigger)
{
    if (!(spacing > 0) || !(trigger > 0) || !(area > 0))
        return 0;
    return int(std::ceil(area / (spacing * trigger)));
}

} // namespace sortie::mission::photogrammetry
