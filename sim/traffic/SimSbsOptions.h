#pragma once

#include <QCommandLineOption>

#include <optional>

class QCommandLineParser;

namespace sortie::sim {

// sortie-sim's --sbs-port PORT: serve the simulated traffic as an SBS-1 feed on this port of the
// HCI listen address. Absent: no feed. 0 picks a free port (printed, like --port 0).
class SimSbsOptions
{
public:
    SimSbsOptions();
    void addTo(QCommandLineParser &parser) const;
    // False with an error naming the option when the value is not a port.
    bool read(const QCommandLineParser &parser, QString *error);

    std::optional<quint16> port; // absent: off

private:
    QCommandLineOption m_option;
};

} // namespace sortie::sim
