#pragma once

#include "Camera.h"

namespace sortie::mission::photogrammetry {

// The arithmetic of a photo survey (shared/ugcs-route-segments.md §4), the same in the client's
// editors and in the simulator's processing. Heights in metres above the ground photographed,
// GSD in cm/px (UgCS's groundSampleDistance unit), overlaps in percent, distances in metres.
// `topForward` is UgCS's camTopFacingForward: the image height runs along the track.

struct Footprint
{
    double across = 0.0;  // metres on the ground across the flight direction
    double along = 0.0;   // metres along it
};

// GSD = H · sensor width / (focal · image width), in cm/px; 0 for an invalid camera.
double gsdAtHeight(const Camera &camera, double height);
// The height that gives this GSD; 0 for an invalid camera.
double heightForGsd(const Camera &camera, double gsdCm);
Footprint footprint(const Camera &camera, double height, bool topForward = true);
// Distance between neighbouring passes, and between photos along a pass.
double passSpacing(double footprintAcross, double overlapSidePercent);
double triggerDistance(double footprintAlong, double overlapForwardPercent);
// The overlap (percent) a spacing gives on a footprint: the inverse of the two above.
double overlapFor(double spacing, double footprintLength);
// Photos a pass of `length` takes: one at each end and every `trigger` metres between.
int photosOnPass(double length, double trigger);
// Seconds between photos at `speed`; never below the camera's shortest interval when it is known.
double triggerInterval(double trigger, double speed, const Camera &camera);
// The fastest ground speed at which the camera can still take a photo every `trigger` metres;
// 0 when the camera's shortest interval is not known (no limit).
double maxSpeedForTrigger(double trigger, const Camera &camera);

// Everything the editor shows as the operator types, from what UgCS's photogrammetry takes.
struct Figures
{
    double height = 0.0;
    double gsdCm = 0.0;
    Footprint footprint;
    double passSpacing = 0.0;
    double triggerDistance = 0.0;
    double triggerIntervalS = 0.0;  // at the given speed
    double maxSpeed = 0.0;          // the camera's limit for this trigger distance; 0 = none known
};
Figures figuresForGsd(const Camera &camera, double gsdCm, double overlapForwardPercent, double overlapSidePercent,
                      bool topForward, double speed);
Figures figuresForHeight(const Camera &camera, double height, double overlapForwardPercent, double overlapSidePercent,
                         bool topForward, double speed);
// Photos expected on an area before it is planned: area / (spacing × trigger), rounded up.
int estimatedPhotos(double areaSquareMeters, double spacing, double trigger);

} // namespace sortie::mission::photogrammetry
