#include "ServerAddress.h"

#include <QHostAddress>

#include <optional>
#include <QCoreApplication>

namespace sortie::client {

namespace {

std::optional<quint16> parsePort(const QString &text)
{
    bool ok = false;
    const uint port = text.toUInt(&ok);
    if (!ok || port == 0 || port > 65535)
        return std::nullopt;
    return quint16(port);
}

} // namespace

std::variant<ServerAddress, QString> ServerAddress::parse(const QString &text)
{
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty())
        return QCoreApplication::translate("ServerAddress", "the server address is empty (expected host:port)");
    if (trimmed.contains(QLatin1String("://")))
        return QCoreApplication::translate("ServerAddress", "\"%1\" is a URL: give the server as host:port, e.g. localhost:3334").arg(trimmed);
    ServerAddress address;
    QString portText;
    if (trimmed.startsWith(QLatin1Char('['))) {
        const qsizetype close = trimmed.indexOf(QLatin1Char(']'));
        if (close < 0)
            return QCoreApplication::translate("ServerAddress", "\"%1\" opens an IPv6 address with [ but never closes it").arg(trimmed);
        address.host = trimmed.mid(1, close - 1);
        const QString rest = trimmed.mid(close + 1);
        if (!rest.isEmpty() && !rest.startsWith(QLatin1Char(':')))
            return QCoreApplication::translate("ServerAddress", "\"%1\" has text after the IPv6 address that is not :port").arg(trimmed);
        portText = rest.mid(1);
        if (QHostAddress(address.host).protocol() != QAbstractSocket::IPv6Protocol)
            return QCoreApplication::translate("ServerAddress", "\"%1\" is not an IPv6 address").arg(address.host);
    } else {
        const qsizetype colon = trimmed.lastIndexOf(QLatin1Char(':'));
        if (colon >= 0 && trimmed.indexOf(QLatin1Char(':')) != colon)
            return QCoreApplication::translate("ServerAddress", "write an IPv6 server address in brackets: [%1]:3334").arg(trimmed);
        address.host = colon >= 0 ? trimmed.left(colon) : trimmed;
        portText = colon >= 0 ? trimmed.mid(colon + 1) : QString();
    }
    if (address.host.isEmpty())
        return QCoreApplication::translate("ServerAddress", "\"%1\" has no host name").arg(trimmed);
    if (address.host.contains(QLatin1Char('/')) || address.host.contains(QLatin1Char(' ')))
        return QCoreApplication::translate("ServerAddress", "\"%1\" is not a host name (expected host:port, e.g. localhost:3334)").arg(address.host);
    if (!portText.isEmpty() || trimmed.endsWith(QLatin1Char(':'))) {
        const auto port = parsePort(portText);
        if (!port)
            return QCoreApplication::translate("ServerAddress", "\"%1\" is not a port number (1 to 65535)").arg(portText);
        address.port = *port;
    }
    return address;
}

QString ServerAddress::toString() const
{
    const QString shown = host.contains(QLatin1Char(':')) ? QStringLiteral("[%1]").arg(host) : host;
    return QStringLiteral("%1:%2").arg(shown).arg(port);
}

} // namespace sortie::client
