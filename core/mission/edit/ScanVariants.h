#pragma once

#include "AreaScanPlanner.h"

#include <QVariantMap>

namespace sortie::mission {

// Area-scan parameters and plans as QVariantMaps for QML. Parameter keys: cameraName,
// sensorWidthMm, sensorHeightMm, focalLengthMm, imageWidthPx, imageHeightPx,
// byGroundSampleDistance, altitude, groundSampleDistanceCm, altitudeType ("AGL"/"AMSL"),
// frontOverlapPercent, sideOverlapPercent, directionDeg, turnaroundMeters, speed.
QVariantMap scanParametersToVariant(const AreaScanParameters &p);
// Applies the keys present in map over p; false (p untouched) when a value is of the wrong kind.
bool applyScanVariant(AreaScanParameters &p, const QVariantMap &map);
// {ok, message, transects, cells, photoCount, altitude, groundSampleDistanceCm,
//  transectSpacingMeters, triggerDistanceMeters, pathLengthMeters, areaSquareMeters,
//  path: [{latitude, longitude}, ...]} — message says why when ok is false.
QVariantMap scanPlanToVariant(const AreaScanOutcome &outcome);

} // namespace sortie::mission
