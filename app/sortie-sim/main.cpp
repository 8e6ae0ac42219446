// sortie-sim: the simulated UgCS server as a program. Wiring only: options -> world -> servers.
#include "HciServer.h"
#include "SimCameraFleet.h"
#include "HciSimOptions.h"
#include "SimSbsOptions.h"
#include "SimSbsServer.h"
#include "SimVciFleet.h"
#include "SimVehicle.h"
#include "SimWorld.h"
#include "VideoRuntime.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QSocketNotifier>

#include <csignal>
#include <memory>
#include <cstdio>
#include <sys/socket.h>
#include <unistd.h>

namespace {
int g_signalPipe[2] = {-1, -1};

// Ctrl-C and SIGTERM quit through the event loop, so the store is saved: the handler only writes a byte.
void quitOnSignals(QCoreApplication &app)
{
    if (::socketpair(AF_UNIX, SOCK_STREAM, 0, g_signalPipe) != 0)
        return;
    auto *notifier = new QSocketNotifier(g_signalPipe[1], QSocketNotifier::Read, &app);
    QObject::connect(notifier, &QSocketNotifier::activated, &app, &QCoreApplication::quit);
    const auto handler = [](int) {
        const char byte = 1;
        [[maybe_unused]] auto n = ::write(g_signalPipe[0], &byte, 1);
    };
    std::signal(SIGINT, handler);
    std::signal(SIGTERM, handler);
}
} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("sortie-sim"));
    quitOnSignals(app);

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Simulated UgCS server: HCI on 127.0.0.1, emulator vehicles near Riga; and VCI vehicles (--vci) on their own ports."));
    parser.addHelpOption();
    sortie::sim::HciSimOptions hci;
    hci.addTo(parser);
    sortie::sim::SimVciFleetOptions vci;
    vci.addTo(parser);
    sortie::sim::SimSbsOptions sbs;
    sbs.addTo(parser);
    sortie::sim::SimCameraOptions cameras;
    cameras.addTo(parser);
    parser.process(app);

    QString error;
    if (!hci.read(parser, &error) || !vci.read(parser, &error) || !sbs.read(parser, &error) || !cameras.read(parser, &error)) {
        std::fprintf(stderr, "sortie-sim: %s\n", qPrintable(error));
        return 2;
    }

    sortie::sim::SimWorld world(hci.world);
    sortie::sim::HciServer server(world);
    server.sessions().setExpiry(hci.sessionExpiryMs);
    server.faults() = hci.faults;
    server.setTls(hci.tls);
    if (!server.listen(hci.address, hci.port)) {
        std::fprintf(stderr, "sortie-sim: %s\n", qPrintable(server.errorString()));
        return 1;
    }
    std::printf("sortie-sim: HCI%s on %s:%u, %d vehicles, telemetry %.0f Hz\n", hci.tls ? " over TLS" : "", qPrintable(hci.address.toString()),
                unsigned(server.port()), int(world.vehicles().size()), hci.world.telemetryRateHz);
    sortie::sim::SimSbsServer sbsServer(world.traffic());
    if (sbs.port) {
        if (!sbsServer.listen(hci.address, *sbs.port)) {
            std::fprintf(stderr, "sortie-sim: --sbs-port: %s\n", qPrintable(sbsServer.errorString()));
            return 1;
        }
        std::printf("sortie-sim: SBS-1 traffic on %s:%u\n", qPrintable(hci.address.toString()), unsigned(sbsServer.port()));
    }
    // The cameras (GStreamer started here, only when asked for): one per server vehicle.
    std::unique_ptr<sortie::video::VideoRuntime> gstreamer;
    std::unique_ptr<sortie::sim::SimCameraFleet> cameraFleet;
    if (cameras.enabled()) {
        gstreamer = std::make_unique<sortie::video::VideoRuntime>();
        cameraFleet = std::make_unique<sortie::sim::SimCameraFleet>(*gstreamer, cameras, hci.address);
        for (size_t i = 0; i < world.vehicles().size(); ++i)
            cameraFleet->addCamera(int(i) + 1, sortie::sim::poseOf(world.vehicles()[i]->model()));
        if (!cameraFleet->start(&error)) {
            std::fprintf(stderr, "sortie-sim: %s\n", qPrintable(error));
            return 1;
        }
        for (size_t i = 0; i < world.vehicles().size(); ++i)
            world.vehicles()[i]->setVideoStreamUri(cameraFleet->streamUri(int(i) + 1));
        for (const QString &line : cameraFleet->describe())
            std::printf("sortie-sim: %s\n", qPrintable(line));
    }
    vci.vehicle.terrain = &world.terrain();  // one ground for every simulated vehicle
    vci.vehicle.energy = hci.world.energy;   // and one energy profile
    vci.tls = hci.tls;                       // and one certificate
    sortie::sim::SimVciFleet fleet(vci);
    if (!fleet.start(&error)) {
        std::fprintf(stderr, "sortie-sim: %s\n", qPrintable(error));
        return 1;
    }
    for (const QString &line : fleet.describe())
        std::printf("sortie-sim: VCI %s\n", qPrintable(line));
    std::fflush(stdout);
    const int code = app.exec();
    world.saveStore();
    return code;
}
