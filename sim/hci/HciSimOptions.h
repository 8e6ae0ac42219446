#pragma once

#include "SimFaults.h"
#include "SimWorld.h"

#include <QCommandLineOption>
#include <QHostAddress>
#include <QList>
#include <QSslConfiguration>

#include <optional>

class QCommandLineParser;

namespace sortie::sim {

// The command-line options of the simulated HCI server, so that sortie-sim's main() only wires:
// --port, --listen, --user, --hci-vehicles, --store, --telemetry-rate, --session-expiry,
// --max-sessions, --no-demo-mission, --energy-profile (every simulated vehicle's, VCI ones too),
// --tls-cert and --tls-key (TLS on every listener that carries a password or commands: HCI and the
// VCI vehicles' TCP ports) and the --fault-* test knobs.
class HciSimOptions
{
public:
    HciSimOptions();
    void addTo(QCommandLineParser &parser) const;
    // Reads the parsed options; false with an error naming the option when one is invalid.
    bool read(const QCommandLineParser &parser, QString *error);

    QHostAddress address = QHostAddress::LocalHost;
    quint16 port = 3334;
    int sessionExpiryMs = 60000;
    SimWorld::Config world;
    SimFaults faults;
    std::optional<QSslConfiguration> tls; // --tls-cert with --tls-key; nullopt: plain TCP

private:
    QList<QCommandLineOption> m_options;
};

} // namespace sortie::sim
