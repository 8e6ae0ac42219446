#include "FleetRecording.h"

#include "FlightRecorder.h"
#include "HciSession.h"
#include "VehicleFleet.h"

#include <QMetaEnum>

namespace sortie::flightlog {

FleetRecording::FleetRecording(client::VehicleFleet *fleet, FlightRecorder *recorder, hci::HciSession *session, QObject *parent)
    : QObject(parent)
    , m_fleet(fleet)
    , m_recorder(recorder)
{
    connect(fleet, &QAbstractItemModel::rowsInserted, this, [this](const QModelIndex &, int first, int last) { addRows(first, last); });
    // Vehicles leaving the fleet are destroyed; the recorder notices that by itself.
    addRows(0, fleet->count() - 1);
    // Every command and upload sent to the fleet's vehicles, whoever sent it, with its result.
    recorder->followCommands(fleet->commandLog());
    if (session) {
        connect(session, &hci::HciSession::stateChanged, this, [this](hci::HciSession::State state) {
            if (m_recorder)
                m_recorder->recordEvent(nullptr, QStringLiteral("server"),
                                        QString::fromLatin1(QMetaEnum::fromType<hci::HciSession::State>().valueToKey(int(state))));
        });
    }
}

void FleetRecording::addRows(int first, int last)
{
    if (!m_fleet || !m_recorder)
        return;
    for (int row = first; row <= last; ++row)
        m_recorder->addVehicle(m_fleet->vehicleAt(row));
}

} // namespace sortie::flightlog
