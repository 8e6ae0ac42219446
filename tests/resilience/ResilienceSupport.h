#pragma once

// Helpers for the fault tests: the operator as the desktop app wires it, and waiting on the event
// loop. tests/support has sortie-sim as a process, free ports and this process's memory and descriptors.
#include "ClientGraph.h"
#include "ConnectionController.h"
#include "FreePort.h"
#include "HciClient.h"
#include "HciSession.h"
#include "MissionController.h"
#include "ProcessStats.h"
#include "VehicleFleet.h"

#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include <chrono>
#include <memory>

namespace sortie::test {

using namespace std::chrono_literals;

// The simulator's demo route, and the row of an object by name in a list the views show (-1: none).
inline const QString kDemoRoute = QStringLiteral("Riga port - 4 WP");

inline int rowOf(const client::ServerObjectListModel &model, const QString &name)
{
    for (int row = 0; row < model.count(); ++row) {
        if (model.nameAt(row) == name)
            return row;
    }
    return -1;
}

// Spins the event loop in 1 ms steps until `done` holds (QTRY_* sleeps 50 ms a step: too slow for
// loops of hundreds). False on timeout.
template<class Predicate>
bool waitUntil(Predicate done, int timeoutMs = 10000)
{
    QDeadlineTimer deadline(timeoutMs);
    while (!done()) {
        if (deadline.hasExpired())
            return false;
        QTest::qWait(1);
    }
    return true;
}

// One operator: the client as the program wires it (ClientGraph), with settings in a folder of its
// own and nothing written to disk (no autosave, no flight log: these tests count descriptors and
// threads). Short backoff, so a restarted server is found again within a second or so.
struct Operator
{
    // withFleet: also the vehicles (their telemetry subscriptions keep the stream busy).
    explicit Operator(bool withFleet = true)
        : storage(dir.filePath(QStringLiteral("sortie.ini")), QSettings::IniFormat)
        , graph(&storage, {{}, {}, {}, withFleet})
        , session(graph.session())
        , client(graph.hciClient())
        , connection(graph.connection())
        , missions(graph.missions())
        , fleet(graph.fleet())
    {
        session.reconnectPolicy().setDelays(100ms, 800ms);
        session.setConnectTimeout(3000ms);
        QObject::connect(&connection, &client::ConnectionController::stateChanged, &connection, [this] {
            if (states.isEmpty() || states.last() != connection.stateName())
                states.append(connection.stateName());
        });
    }

    bool logIn(const QString &address, int timeoutMs = 10000)
    {
        if (!connection.connectToServer(address, QStringLiteral("admin"), QStringLiteral("admin")))
            return false;
        QDeadlineTimer deadline(timeoutMs);
        while (!connection.isReady() && !deadline.hasExpired())
            QTest::qWait(10);
        return connection.isReady();
    }

    QTemporaryDir dir;
    QSettings storage;
    client::ClientGraph graph;
    hci::HciSession &session;
    hci::HciClient &client;
    client::ConnectionController &connection;
    client::MissionController &missions;
    client::VehicleFleet *fleet; // nullptr without the fleet
    QStringList states; // every state the operator saw, in order
};

} // namespace sortie::test
