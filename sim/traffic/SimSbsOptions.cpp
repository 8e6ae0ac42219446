#include "SimSbsOptions.h"

#include <QCommandLineParser>

namespace sortie::sim {

SimSbsOptions::SimSbsOptions()
    : m_option(QStringLiteral("sbs-port"),
               QStringLiteral("Serve the simulated ADS-B traffic as an SBS-1 (BaseStation) feed on this TCP port, as dump1090 does on 30003 "
                              "(default: off; 0 picks a free one)."),
               QStringLiteral("port"))
{
}

void SimSbsOptions::addTo(QCommandLineParser &parser) const
{
    parser.addOption(m_option);
}

bool SimSbsOptions::read(const QCommandLineParser &parser, QString *error)
{
    if (!parser.isSet(m_option))
        return true;
    bool ok = false;
    const uint value = parser.value(m_option).toUInt(&ok);
    if (!ok || value > 65535) {
        *error = QStringLiteral("--sbs-port: expected a port from 0 to 65535, got '%1'").arg(parser.value(m_option));
        return false;
    }
    port = quint16(value);
    return true;
}

} // namespace sortie::sim
