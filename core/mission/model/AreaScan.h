#pragma once

#include "Camera.h"
#include "GeoPoint.h"
#include "ServerOrigin.h"
#include "WaypointAction.h"

#include <QString>

#include <optional>
#include <vector>

namespace sortie::mission {

// What the operator chose for a scan: the altitude itself, or the ground sample distance the
// altitude is derived from.
enum class ScanHeightMode { Altitude, GroundSampleDistance };

struct AreaScanParameters
{
    Camera camera;
    ScanHeightMode heightMode = ScanHeightMode::Altitude;
    double altitude = 60.0;                 // metres, used in Altitude mode
    double groundSampleDistanceCm = 2.0;    // cm/px, used in GroundSampleDistance mode
    AltitudeType altitudeType = AltitudeType::Agl;
    double frontOverlapPercent = 75.0;
    double sideOverlapPercent = 65.0;
    double directionDeg = 0.0;              // bearing of the transects, clockwise from north
    double turnaroundMeters = 10.0;         // overshoot beyond each transect end, for the turn
    double speed = 8.0;                     // m/s along the transects
    double sideDistanceMeters = 0.0;        // UgCS sideDistance: metres between passes; 0 = from footprint and side overlap
    // UgCS tolerance, flown AGL: how far the ground may depart from a pass before terrain following
    // adds a point there (metres). Unset: the server's own (3 m, kDefaultFollowTolerance).
    std::optional<double> toleranceMeters;
    bool operator==(const AreaScanParameters &) const = default;
};

// The altitude the scan flies at (derived from the GSD in GroundSampleDistance mode) and the
// ground sample distance it achieves (the coarser of the two image axes), in cm/px.
double scanAltitude(const AreaScanParameters &p);
double scanGroundSampleDistanceCm(const AreaScanParameters &p);
// Ground footprint of one image at the scan altitude, metres across and along the flight line.
double footprintAcrossMeters(const AreaScanParameters &p);
double footprintAlongMeters(const AreaScanParameters &p);
// Sets the field the height mode does not use (altitude in GSD mode, GSD in altitude mode) to the
// value derived from the other, so that what is shown, saved and compared is consistent.
void syncDerivedFields(AreaScanParameters &p);

// An area-scan segment: a polygon (degrees, not closed: the last vertex connects to the first)
// and the parameters the lawnmower path is generated from.
struct AreaScan
{
    std::vector<GeoPoint> polygon;
    AreaScanParameters parameters;
    ServerOrigin origin;
    bool operator==(const AreaScan &) const = default;
};

} // namespace sortie::mission
