#include "DemoServer.h"

#include "HciServer.h"
#include "SimSbsServer.h"
#include "SimVciFleet.h"
#include "SimVciListener.h"
#include "SimVehicle.h"
#include "SimCameraFleet.h"
#include "SimWorld.h"
#include "VideoRuntime.h"

#include "Messages.pb.h"

namespace sortie::app {

DemoServer::DemoServer() = default;
DemoServer::~DemoServer() = default;

namespace {

namespace pb = com::ugcs::ucs::proto;

void addArgument(pb::Command &command, const char *code, double value)
{
    auto *argument = command.add_arguments();
    argument->set_code(code);
    argument->mutable_value()->set_doublevalue(value);
}

// Arms the vehicle and sends it 5 km north at 60 m and 10 m/s: several minutes of flight over the
// demo area (away from the airport's zone), through the simulator's own commands.
bool flyNorth(sim::SimVehicle &vehicle, QString *error)
{
    constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;
    constexpr double kNorthDeg = 5000.0 / 111320.0; // 5 km of latitude
    pb::Command arm;
    arm.set_code("arm");
    pb::Command go;
    go.set_code("waypoint");
    const auto &state = vehicle.model().state();
    addArgument(go, "latitude", (state.latitude + kNorthDeg) * kRadPerDeg);
    addArgument(go, "longitude", state.longitude * kRadPerDeg);
    addArgument(go, "altitude_agl", 60);
    addArgument(go, "ground_speed", 10);
    for (const pb::Command &command : {arm, go}) {
        const auto result = vehicle.execute(command);
        if (result.commandstatus() != pb::CS_SUCCEEDED) {
            *error = QStringLiteral("the demo vehicle refused %1: %2")  // i18n: not text (a start-up failure for the terminal)
                         .arg(QString::fromStdString(command.code()), QString::fromStdString(result.errormessage()));
            return false;
        }
    }
    return true;
}

} // namespace

bool DemoServer::start(QString *error, Scene scene)
{
    sim::SimWorld::Config config;
    config.users = {{0, user(), password(), true}};
    config.mannedTraffic = scene == Scene::Full;
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
    if (scene == Scene::Flying) {
        if (!m_world->start(error) || m_world->vehicles().empty())
            return false;
        sim::SimVehicle &first = *m_world->vehicles().front();
        if (!flyNorth(first, error))
            return false;
        m_flyingVehicle = QString::fromStdString(first.vehicle().name());
    }
    if (scene != Scene::Full)
        return true; // no VCI vehicle: it would be a fourth one on the map, and no camera (the idle benchmark)
    // Each server vehicle's camera over RTSP, published as its video_stream_uri; encoded only while
    // the client watches it. 640x360: the demo shares its machine with the client's decoder.
    if (!m_world->start(error))
        return false;
    m_gstreamer = std::make_unique<video::VideoRuntime>();
    sim::SimCameraOptions cameras;
    cameras.rtspPort = 0;
    cameras.format = sim::SimCameraFormat{640, 360, 30, 1500};
    m_cameras = std::make_unique<sim::SimCameraFleet>(*m_gstreamer, cameras, QHostAddress(QHostAddress::LocalHost));
    for (size_t i = 0; i < m_world->vehicles().size(); ++i)
        m_cameras->addCamera(int(i) + 1, sim::poseOf(m_world->vehicles()[i]->model()));
    if (!m_cameras->start(error))
        return false;
    for (size_t i = 0; i < m_world->vehicles().size(); ++i)
        m_world->vehicles()[i]->setVideoStreamUri(m_cameras->streamUri(int(i) + 1));
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
