#pragma once

#include "SimServices.h"

#include <QString>

namespace sortie::sim {

class HciRequestDispatcher;
class SimVehicle;
struct SimCall;

// SendCommand, UploadRoute (with OperationStatus progress before the answer), ProcessRoute and
// GetTelemetry for the simulated vehicles. A vehicle locked by another session refuses commands
// and uploads.
class SimVehicleService
{
public:
    explicit SimVehicleService(SimServices services);
    void install(HciRequestDispatcher &dispatcher);

    // Time between two progress reports of an upload.
    void setUploadStepMs(int ms) { m_uploadStepMs = ms; }

private:
    void sendCommand(SimCall &call);
    void uploadRoute(SimCall &call);
    void processRoute(SimCall &call);
    void selectionValues(SimCall &call);
    void telemetry(SimCall &call);
    QString lockedBy(const SimCall &call, int vehicleId) const;

    SimServices m_s;
    int m_uploadStepMs = 40;
};

} // namespace sortie::sim
