#pragma once

#include <QObject>
#include <QPointer>

namespace sortie::hci {
class HciSession;
}
namespace sortie::client {
class VehicleFleet;
}

namespace sortie::flightlog {

class FlightRecorder;

// Records every vehicle of a fleet, the ones there now and the ones that come, the commands its
// command log sees, and the server connection's changes. The one wiring of a recorder to the client, used by the desktop client and
// by `sortie-log record`.
class FleetRecording : public QObject
{
    Q_OBJECT

public:
    FleetRecording(client::VehicleFleet *fleet, FlightRecorder *recorder, hci::HciSession *session = nullptr,
                   QObject *parent = nullptr);

private:
    void addRows(int first, int last);

    QPointer<client::VehicleFleet> m_fleet;
    QPointer<FlightRecorder> m_recorder;
};

} // namespace sortie::flightlog
