#include "AreaScan.h"

#include <algorithm>

namespace sortie::mission {

namespace {
// metres of ground per pixel per metre of altitude, the coarser axis
double gsdPerMeterAltitude(const Camera &c)
{
    if (c.focalLengthMm <= 0 || c.imageWidthPx <= 0 || c.imageHeightPx <= 0)
        return 0.0;
    return std::max(c.sensorWidthMm / (c.focalLengthMm * c.imageWidthPx),
                    c.sensorHeightMm / (c.focalLengthMm * c.imageHeightPx));
}
}

double scanAltitude(const AreaScanParameters &p)
{
    if (p.heightMode == ScanHeightMode::Altitude)
        return p.altitude;
    const double k = gsdPerMeterAltitude(p.camera);
    return k > 0 ? p.groundSampleDistanceCm / 100.0 / k : 0.0;
}

double scanGroundSampleDistanceCm(const AreaScanParameters &p)
{
    if (p.heightMode == ScanHeightMode::GroundSampleDistance)
        return p.groundSampleDistanceCm;
    return scanAltitude(p) * gsdPerMeterAltitude(p.camera) * 100.0;
}

double footprintAcrossMeters(const AreaScanParameters &p)
{
    return p.camera.focalLengthMm > 0 ? scanAltitude(p) * p.camera.sensorWidthMm / p.camera.focalLengthMm : 0.0;
}

double footprintAlongMeters(const AreaScanParameters &p)
{
    return p.camera.focalLengthMm > 0 ? scanAltitude(p) * p.camera.sensorHeightMm / p.camera.focalLengthMm : 0.0;
}

void syncDerivedFields(AreaScanParameters &p)
{
    if (p.heightMode == ScanHeightMode::Altitude)
        p.groundSampleDistanceCm = scanGroundSampleDistanceCm(p);
    else
        p.altitude = scanAltitude(p);
}

} // namespace sortie::mission
