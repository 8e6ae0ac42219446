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
    QString trimmed = text.trimmed();
    if (trimmed.isEmpty())
        return QCoreApplication::translate("ServerAddress", "the server address is empty (expected host:port)");
    ServerAddress address;
    if (trimmed.startsWith(QLatin1String("tls://"), Qt::CaseInsensitive)) {
        address.tls = true;
        trimmed = trimmed.mid(6);
    }
    if (trimmed.contains(QLatin1String("://")))
        return QCoreApplication::translate("ServerAddress", "\"%1\" is a URL: give the server as host:port, e.g. localhost:3334 (or tls://host:port over TLS)").arg(text.trimmed());
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

QString ServerAddress::peer() const
{
    const QString shown = host.contains(QLatin1Char(':')) ? QStringLiteral("[%1]").arg(host) : host;
    return QStringLiteral("%1:%2").arg(shown).arg(port);
}

QString ServerAddress::toString() const
{
    return tls ? QStringLiteral("tls://") + peer() : peer();
}

bool ServerAddress::isLoopback() const
{
    const QString name = host.toLower();
    if (name == QLatin1String("localhost") || name.endsWith(QLatin1String(".localhost")))
        return true;
    QHostAddress address;
    if (!address.setAddress(host))
        return false; // a name: where it leads is up to DNS
    bool mapped = false;
    const quint32 v4 = address.toIPv4Address(&mapped); // ::ffff:127.0.0.1 too
    if (mapped)
        return (v4 >> 24) == 127;
    return address == QHostAddress(QHostAddress::LocalHostIPv6);
}

} // namespace sortie::client
