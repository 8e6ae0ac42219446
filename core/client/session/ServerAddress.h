#pragma once

#include <QString>

#include <variant>

namespace sortie::client {

// host:port of a UgCS server ([v6:address]:port for IPv6; port 3334 when left out).
struct ServerAddress
{
    QString host;
    quint16 port = 3334;

    // The address, or a one-line reason an operator understands.
    static std::variant<ServerAddress, QString> parse(const QString &text);
    QString toString() const;
};

} // namespace sortie::client
