#pragma once

#include <QUdpSocket>

namespace sortie::test {

// A loopback UDP port nobody is bound to right now.
inline quint16 freeUdpPort()
{
    QUdpSocket probe;
    return probe.bind(QHostAddress::LocalHost, 0) ? probe.localPort() : 0;
}

} // namespace sortie::test
