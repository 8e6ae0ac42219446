#pragma once

// Shared by the HCI integration tests: a simulated server on an ephemeral loopback port and small
// helpers to wait on replies and sessions without sleeping.
#include "HciReply.h"
#include "HciServer.h"
#include "HciSession.h"
#include "SimWorld.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

namespace sortie::test {

struct SimServer
{
    explicit SimServer(sim::SimWorld::Config config = fastConfig())
        : world(std::move(config))
        , server(world)
    {
        server.setUploadStepMs(5);
        if (!server.listen(QHostAddress::LocalHost, 0))
            qFatal("cannot start the simulator: %s", qPrintable(server.errorString()));
    }

    static sim::SimWorld::Config fastConfig()
    {
        sim::SimWorld::Config c;
        c.telemetryRateHz = 20;
        c.users = {{0, QStringLiteral("admin"), QStringLiteral("admin"), true}, {0, QStringLiteral("bob"), QStringLiteral("s3cret-bob"), false}};
        return c;
    }

    quint16 port() const { return server.port(); }

    sim::SimWorld world;
    sim::HciServer server;
};

// Keeps a reply alive past finished() so a test can inspect it.
inline std::unique_ptr<hci::HciReply> keep(hci::HciReply *reply)
{
    reply->setAutoDelete(false);
    return std::unique_ptr<hci::HciReply>(reply);
}

inline bool finishes(hci::HciReply *reply, int ms = 10000)
{
    if (reply->isFinished())
        return true;
    QSignalSpy spy(reply, &hci::HciReply::finished);
    return spy.wait(ms);
}

inline bool reaches(hci::HciSession &session, hci::HciSession::State state, int ms = 10000)
{
    QDeadlineTimer deadline(ms);
    while (session.state() != state && !deadline.hasExpired())
        QTest::qWait(5);
    return session.state() == state;
}

} // namespace sortie::test
