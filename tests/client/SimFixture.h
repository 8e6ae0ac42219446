#pragma once

// A simulated UgCS server on an ephemeral loopback port, for the client-layer tests.
#include "HciServer.h"
#include "SimWorld.h"

#include <QString>

namespace sortie::test {

struct SimFixture
{
    explicit SimFixture(sim::SimWorld::Config config = defaults())
        : world(std::move(config))
        , server(world)
    {
        server.setUploadStepMs(5);
        if (!server.listen(QHostAddress::LocalHost, 0))
            qFatal("cannot start the simulator: %s", qPrintable(server.errorString()));
    }

    static sim::SimWorld::Config defaults()
    {
        sim::SimWorld::Config c;
        c.telemetryRateHz = 20;
        c.users = {{0, QStringLiteral("admin"), QStringLiteral("admin"), true},
                   {0, QStringLiteral("bob"), QStringLiteral("s3cret-bob"), false}};
        return c;
    }

    QString address() const { return QStringLiteral("127.0.0.1:%1").arg(server.port()); }

    sim::SimWorld world;
    sim::HciServer server;
};

} // namespace sortie::test
