#pragma once

#include <QString>
#include <QStringList>

#include <memory>

namespace sortie::video {
class VideoRuntime;
}

namespace sortie::sim {
class HciServer;
class SimCameraFleet;
class SimSbsServer;
class SimVciFleet;
class SimWorld;
} // namespace sortie::sim

namespace sortie::app {

// --demo: the simulated UgCS server (with its vehicles) and a simulated VCI vehicle running inside
// the client on free loopback ports (and its manned traffic as an SBS-1 feed), so the first launch has something real to talk to.
class DemoServer
{
public:
    // What moves in the demo. Full: everything above. Parked: the server's three vehicles on the
    // ground, an empty sky and no VCI vehicle (nothing on screen moves). Flying: Parked, but the
    // server's first vehicle flies 5 km north as soon as the simulator starts (benchmarks).
    enum class Scene { Full, Parked, Flying };

    DemoServer();
    ~DemoServer();

    bool start(QString *error, Scene scene = Scene::Full);
    // The vehicle Scene::Flying sends off ("EMU-101"); empty in the other scenes.
    QString flyingVehicleName() const { return m_flyingVehicle; }
    QString address() const;       // "127.0.0.1:<port>"
    QStringList vciAddresses() const; // "tcp://127.0.0.1:<port>", one per VCI vehicle
    QString sbsAddress() const;       // "127.0.0.1:<port>": the simulated traffic as an SBS-1 feed
    static QString user() { return QStringLiteral("admin"); }
    static QString password() { return QStringLiteral("admin"); }

private:
    std::unique_ptr<sim::SimWorld> m_world;
    std::unique_ptr<sim::HciServer> m_server;
    std::unique_ptr<sim::SimVciFleet> m_vci;
    std::unique_ptr<sim::SimSbsServer> m_sbs;
    // The vehicles' cameras (the full scene only): GStreamer started for them, their RTSP server.
    std::unique_ptr<video::VideoRuntime> m_gstreamer;
    std::unique_ptr<sim::SimCameraFleet> m_cameras;
    QString m_flyingVehicle;
};

} // namespace sortie::app
