#pragma once
// Shared by the tests of the server's zones (tst_serverzones, tst_zonesharing): sortie-sim's HCI
// server with two operators (admin, bob) on 127.0.0.1, and one operator's view of its zones.
#include "HciClient.h"
#include "HciServer.h"
#include "HciSession.h"
#include "ServerZones.h"
#include "SimWorld.h"

#include <QSignalSpy>

#include <memory>

namespace sortie::airspace::test {

constexpr int kWait = 15000;
inline const mission::GeoBox kDemoBox{56.90, 23.90, 57.01, 24.12, false};

// sortie-sim's HCI server with the users admin/admin and bob/s3cret-bob.
struct TwoOperatorServer
{
    std::unique_ptr<sim::SimWorld> world;
    std::unique_ptr<sim::HciServer> server;

    TwoOperatorServer()
    {
        sim::SimWorld::Config config;
        config.users = {{0, QStringLiteral("admin"), QStringLiteral("admin"), true},
                        {0, QStringLiteral("bob"), QStringLiteral("s3cret-bob"), false}};
        world = std::make_unique<sim::SimWorld>(config);
        server = std::make_unique<sim::HciServer>(*world);
        if (!server->listen(QHostAddress::LocalHost, 0))
            qFatal("sortie-sim's HCI server does not listen on 127.0.0.1");
    }
    quint16 port() const { return server->port(); }
};

// One operator: a session, its client and its view of the server's zones, answered once.
struct Operator
{
    hci::HciSession session;
    hci::HciClient client{&session};
    ServerZones zones{&client};

    Operator(quint16 port, const QString &login, const QString &password, const mission::GeoBox &box = kDemoBox)
    {
        zones.setViewBox(box);
        QSignalSpy answered(&zones, &ServerZones::answered);
        session.open(QStringLiteral("127.0.0.1"), port, login, password);
        if (!answered.wait(kWait))
            qFatal("%s: no zones from the simulator", qPrintable(login));
    }

    const Zone *find(const QString &name) const
    {
        for (const Zone &z : zones.zones())
            if (z.name == name)
                return &z;
        return nullptr;
    }
};

} // namespace sortie::airspace::test
