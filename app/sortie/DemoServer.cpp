#include "DemoServer.h"

#include "HciServer.h"
#include "SimSbsServer.h"
#include "SimVciFleet.h"
#include "SimVciListener.h"
#include "SimWorld.h"

namespace sortie::app {

DemoServer::DemoServer() = default;
DemoServer::~DemoServer() = default;

bool DemoServer::start(QString *error)
{
    sim::SimWorld::Config config;
    config.users = {{0, user(), password(), true}};
    m_world = std::make_unique<sim::SimWorld>(config);
    m_server = std::make_unique<sim::HciServer>(*m_world);
    if (!m_server->listen(QHostAddress::LocalHost, 0)) {
        *error = m_server->errorString();
        return false;
    }
    m_sbs = std::make_unique<sim::SimSbsServer>(m_world->traffic());
    if (!m_sbs->listen(QHostAddress::LocalHost, 0)) {
        *error = m_sbs->errorString();
        return false;
    }
    sim::SimVciFleetOptions vci;
    vci.count = 1;
    vci.firstPort = 0; // any free port
    vci.vehicle.terrain = &m_world->terrain();
    m_vci = std::make_unique<sim::SimVciFleet>(vci);
    return m_vci->start(error);
}

QStringList DemoServer::vciAddresses() const
{
    QStringList addresses;
    if (m_vci) {
        for (const auto &listener : m_vci->listeners())
            addresses.append(QStringLiteral("tcp://127.0.0.1:%1").arg(listener->port()));
    }
    return addresses;
}

QString DemoServer::sbsAddress() const
{
    return m_sbs ? QStringLiteral("127.0.0.1:%1").arg(m_sbs->port()) : QString();
}

QString DemoServer::address() const
{
    return m_server ? QStringLiteral("127.0.0.1:%1").arg(m_server->port()) : QString();
}

} // namespace sortie::app
