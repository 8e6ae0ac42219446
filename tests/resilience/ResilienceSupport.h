#pragma once

// Helpers for the fault tests: the operator as the desktop app wires it, and this process's memory
// and descriptors (SimProcess.h has sortie-sim as a process).
#include "ConnectionController.h"
#include "HciClient.h"
#include "HciSession.h"
#include "MissionController.h"
#include "VehicleFleet.h"

#include <QDir>
#include <QFile>
#include <QTcpServer>
#include <QTest>

#include <chrono>
#include <memory>

namespace sortie::test {

using namespace std::chrono_literals;

// Resident memory of this process in KiB (VmRSS), or -1.
inline qint64 rssKiB()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').value(0).toLongLong();
    }
    return -1;
}

// Open file descriptors of this process (sockets, pipes, files, event fds).
inline int openFds()
{
    return int(QDir(QStringLiteral("/proc/self/fd")).entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot).size());
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

// A port nobody listens on right now: bind port 0, note the port, let it go.
inline quint16 freePort()
{
    QTcpServer probe;
    if (!probe.listen(QHostAddress::LocalHost, 0))
        return 0;
    return probe.serverPort();
}

// One operator: session, client and the controllers the views bind to. Short backoff, so a restarted
// server is found again within a second or so.
struct Operator
{
    // withFleet: also the vehicles (their telemetry subscriptions keep the stream busy).
    explicit Operator(bool withFleet = true)
        : client(&session)
        , connection(&session)
        , missions(&client)
        , fleet(withFleet ? std::make_unique<client::VehicleFleet>(&client) : nullptr)
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

    hci::HciSession session;
    hci::HciClient client;
    client::ConnectionController connection;
    client::MissionController missions;
    std::unique_ptr<client::VehicleFleet> fleet;
    QStringList states; // every state the operator saw, in order
};

} // namespace sortie::test
