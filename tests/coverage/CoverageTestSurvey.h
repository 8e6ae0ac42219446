#pragma once
// A lawnmower survey the coverage tests and benchmark fly in their heads: legs north and south
// across a rectangle near Riga, photos at a spacing that gives the forward and side overlap asked
// for with the camera given, at a height above flat ground.
#include "CoverageMap.h"
#include "LocalTangentPlane.h"

namespace sortie::test {

inline mission::Camera surveyCamera()
{
    mission::Camera c; // a 1" 20 MP camera: 150 × 100 m on the ground from 100 m
    c.name = QStringLiteral("Test 1\" 20 MP");
    c.sensorWidthMm = 13.2;
    c.sensorHeightMm = 8.8;
    c.focalLengthMm = 8.8;
    c.imageWidthPx = 5472;
    c.imageHeightPx = 3648;
    return c;
}

struct Survey
{
    double widthMeters = 400, lengthMeters = 400, height = 100;
    double forward = 0.8, side = 0.7;
    mission::GeoPoint origin{56.9500, 24.1000};
};

inline std::vector<coverage::Shot> flySurvey(const Survey &s, const mission::Camera &camera)
{
    const double along = s.height * camera.sensorHeightMm / camera.focalLengthMm * (1 - s.forward);
    const double across = s.height * camera.sensorWidthMm / camera.focalLengthMm * (1 - s.side);
    const mission::LocalTangentPlane plane(s.origin);
    std::vector<coverage::Shot> shots;
    int leg = 0;
    for (double x = 0; x <= s.widthMeters + 1e-6; x += across, ++leg) {
        const bool north = leg % 2 == 0;
        const int n = int(std::floor(s.lengthMeters / along + 1e-9)) + 1;
        for (int i = 0; i < n; ++i) {
            const double y = north ? i * along : s.lengthMeters - i * along;
            const mission::GeoPoint p = plane.unproject({x, y});
            coverage::Shot shot;
            shot.name = QStringLiteral("IMG_%1.JPG").arg(shots.size() + 1, 4, 10, QLatin1Char('0'));
            shot.latitude = p.latitude;
            shot.longitude = p.longitude;
            shot.heightAboveGround = s.height;
            shot.headingDegrees = north ? 0 : 180;
            shots.push_back(shot);
        }
    }
    return shots;
}

} // namespace sortie::test
