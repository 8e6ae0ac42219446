#pragma once

#include <QString>

#include <variant>

namespace sortie::client {

// host:port of a UgCS server ([v6:address]:port for IPv6; port 3334 when left out), plain HCI, or
// tls://host:port for HCI over TLS (a server behind a TLS terminator).
struct ServerAddress
{
    QString host;
    quint16 port = 3334;
    bool tls = false;

    // The address, or a one-line reason an operator understands.
    static std::variant<ServerAddress, QString> parse(const QString &text);
    // "host:port", "[v6]:port", "tls://host:port".
    QString toString() const;
    // host:port alone: what certificates and the operator's answers are remembered by.
    QString peer() const;
    // The host is this computer: an address in 127.0.0.0/8 (IPv4-mapped too) or ::1, or the name
    // "localhost" (or a name under .localhost), which RFC 6761 reserves for the loopback interface.
    // Any other name or address may be across a network.
    bool isLoopback() const;
};

} // namespace sortie::client
