#pragma once

#include <QTcpServer>

namespace sortie::test {

// A loopback port nobody listens on right now, for a server that must be started (and restarted)
// on a port known in advance.
inline quint16 freePort()
{
    QTcpServer probe;
    return probe.listen(QHostAddress::LocalHost, 0) ? probe.serverPort() : 0;
}

} // namespace sortie::test
