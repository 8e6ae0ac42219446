#pragma once

#include "SimServices.h"

namespace sortie::sim {

class HciRequestDispatcher;
struct SimCall;

// Route exports a UgCS server answers with file bytes: ExportRouteToWpmlRequest (172) gets the DJI
// WPML KMZ of the processed route, written by Sortie's own exporter (mission/formats) for the DJI
// aircraft its vehicle profile names, so the SDK's ExportRouteToWpml sample runs against the
// simulator. The processed waypoints give the flown path (AMSL); the planned route gives each
// waypoint's actions. W_RELATIVE_TO_FIRST_WP writes heights above the ground at the first
// waypoint, where the aircraft takes off and climbs first; W_AMSL writes an EGM96 template.
class SimExportService
{
public:
    explicit SimExportService(SimServices services);
    void install(HciRequestDispatcher &dispatcher);

private:
    void exportRouteToWpml(SimCall &call);

    SimServices m_s;
};

} // namespace sortie::sim
