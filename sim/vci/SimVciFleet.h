#pragma once

#include "SimVciOptions.h"

#include <QList>
#include <QObject>
#include <QSslConfiguration>
#include <QStringList>

#include <memory>
#include <optional>
#include <vector>

class QCommandLineParser;

namespace sortie::sim {

class SimVciListener;
class SimVciVehicle;

// sortie-sim's VCI vehicles: how many, where they listen, how they misbehave.
struct SimVciFleetOptions
{
    int count = 0;             // --vci N
    quint16 firstPort = 5760;  // --vci-port: vehicle i listens on firstPort + i (0: any free port)
    bool pty = false;          // --vci-pty: each also on a pseudo-terminal
    SimVciOptions vehicle;     // rate, time scale, framing and the test knobs, shared by all
    std::optional<QSslConfiguration> tls; // sortie-sim's --tls-cert/--tls-key: TLS on every TCP port

    void addTo(QCommandLineParser &parser) const;
    bool read(const QCommandLineParser &parser, QString *error);
};

// N simulated VCI vehicles, each with its own TCP port on 127.0.0.1 (and pty on request), placed a
// few hundred metres apart around the configured home.
class SimVciFleet : public QObject
{
    Q_OBJECT
public:
    explicit SimVciFleet(const SimVciFleetOptions &options, QObject *parent = nullptr);
    ~SimVciFleet() override;

    // Opens every listener; false and an error when a port or a pty cannot be had.
    bool start(QString *error);
    // "vci-1 tcp://127.0.0.1:5760 serial:/dev/pts/4" (vci+tls:// over TLS), one line per vehicle.
    QStringList describe() const;

    const std::vector<std::unique_ptr<SimVciVehicle>> &vehicles() const { return m_vehicles; }
    const std::vector<std::unique_ptr<SimVciListener>> &listeners() const { return m_listeners; }

private:
    SimVciFleetOptions m_options;
    std::vector<std::unique_ptr<SimVciVehicle>> m_vehicles;
    std::vector<std::unique_ptr<SimVciListener>> m_listeners;
};

} // namespace sortie::sim
