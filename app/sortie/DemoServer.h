#pragma once

#include <QString>

#include <memory>

namespace sortie::sim {
class HciServer;
class SimWorld;
} // namespace sortie::sim

namespace sortie::app {

// --demo: the simulated UgCS server (and its vehicles) running inside the client on a free
// loopback port, so the first launch has something real to talk to.
class DemoServer
{
public:
    DemoServer();
    ~DemoServer();

    bool start(QString *error);
    QString address() const;       // "127.0.0.1:<port>"
    static QString user() { return QStringLiteral("admin"); }
    static QString password() { return QStringLiteral("admin"); }

private:
    std::unique_ptr<sim::SimWorld> m_world;
    std::unique_ptr<sim::HciServer> m_server;
};

} // namespace sortie::app
