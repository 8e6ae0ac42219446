#include "MissionProgress.h"

#include <cmath>

namespace sortie::vehicle {

namespace {
// Below this the vehicle is taken as standing (on the ground, or holding): its speed says nothing.
constexpr double kMovingSpeed = 0.5;
} // namespace

QGeoCoordinate coordinateOf(const MissionItem &item)
{
    return QGeoCoordinate(item.latitude, item.longitude);
}

double bearingBetween(const QGeoCoordinate &from, const QGeoCoordinate &to)
{
    if (!from.isValid() || !to.isValid())
        return qQNaN();
    const double degrees = from.azimuthTo(to);
    return degrees < 0 ? degrees + 360.0 : degrees;
}

MissionProgress MissionProgress::compute(const std::vector<MissionItem> &mission, int active, const QGeoCoordinate &position,
                                         double groundSpeed, double cruiseSpeed)
{
    MissionProgress progress;
    progress.count = int(mission.size());
    progress.active = active < 0 ? -1 : active;
    if (progress.isComplete()) {
        progress.distanceLeft = 0;
        progress.timeLeft = 0;
        return progress;
    }
    if (!progress.isFlying() || !position.isValid())
        return progress;
    const double fallback = std::isfinite(groundSpeed) && groundSpeed > kMovingSpeed ? groundSpeed : cruiseSpeed;
    auto speedOf = [&](const MissionItem &item) { return item.speed > 0 ? item.speed : fallback; };

    const QGeoCoordinate target = coordinateOf(mission[size_t(progress.active)]);
    progress.distanceToActive = position.distanceTo(target);
    progress.bearingToActive = bearingBetween(position, target);
    double distance = progress.distanceToActive;
    double time = distance / speedOf(mission[size_t(progress.active)]);
    for (size_t i = size_t(progress.active) + 1; i < mission.size(); ++i) {
        const double leg = coordinateOf(mission[i - 1]).distanceTo(coordinateOf(mission[i]));
        distance += leg;
        time += leg / speedOf(mission[i]);
    }
    progress.distanceLeft = distance;
    progress.timeLeft = time;
    return progress;
}

} // namespace sortie::vehicle
