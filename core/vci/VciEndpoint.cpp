#include "VciEndpoint.h"

#include "CertificateFingerprint.h"

#include <QUrl>
#include <QUrlQuery>
#include <QCoreApplication>

namespace sortie::vci {
namespace {

std::optional<VciEndpoint> failWith(QString *error, const QString &message)
{
    if (error)
        *error = message;
    return std::nullopt;
}

} // namespace

std::optional<VciEndpoint> VciEndpoint::parse(const QString &text, QString *error)
{
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid())
        return failWith(error, QCoreApplication::translate("VciEndpoint", "\"%1\" is not a URL: %2").arg(text, url.errorString()));
    VciEndpoint e;
    const QString scheme = url.scheme().toLower();
    if (scheme == QLatin1String("tcp") || scheme == QLatin1String("vci+tls")) {
        e.kind = Kind::Tcp;
        e.tls = scheme != QLatin1String("tcp");
        e.host = url.host();
        const int port = url.port(-1);
        if (e.host.isEmpty() || port <= 0 || port > 65535)
            return failWith(error, QCoreApplication::translate("VciEndpoint", "\"%1\" needs a host and a port: %2://host:port").arg(text, scheme));
        e.port = quint16(port);
        const QUrlQuery query(url);
        for (const auto &[key, value] : query.queryItems(QUrl::FullyDecoded)) {
            if (!e.tls || key.toLower() != QLatin1String("sha256"))
                return failWith(error, QCoreApplication::translate("VciEndpoint", "\"%1\": unknown setting \"%2\" (vci+tls:// knows sha256=)").arg(text, key));
            const auto pin = tls::normalizedFingerprint(value);
            if (!pin)
                return failWith(error, QCoreApplication::translate("VciEndpoint", "\"%1\": sha256=%2 is not a SHA-256 fingerprint (64 hex digits)").arg(text, value));
            e.pinnedSha256 = *pin;
        }
        return e;
    }
    if (scheme != QLatin1String("serial"))
        return failWith(error, QCoreApplication::translate("VciEndpoint", "\"%1\": use tcp://host:port, vci+tls://host:port or serial:/dev/name").arg(text));

    e.kind = Kind::Serial;
    e.device = url.path();
    if (e.device.isEmpty())
        return failWith(error, QCoreApplication::translate("VciEndpoint", "\"%1\" names no serial device").arg(text));
    const QUrlQuery query(url);
    for (const auto &[key, value] : query.queryItems(QUrl::FullyDecoded)) {
        const QString k = key.toLower(), v = value.toLower();
        bool good = true;
        if (k == QLatin1String("baud")) {
            e.baudRate = v.toInt(&good);
            good = good && e.baudRate > 0;
        } else if (k == QLatin1String("databits")) {
            const int bits = v.toInt(&good);
            good = good && bits >= 5 && bits <= 8;
            e.dataBits = QSerialPort::DataBits(bits);
        } else if (k == QLatin1String("parity")) {
            if (v == QLatin1String("none")) e.parity = QSerialPort::NoParity;
            else if (v == QLatin1String("even")) e.parity = QSerialPort::EvenParity;
            else if (v == QLatin1String("odd")) e.parity = QSerialPort::OddParity;
            else if (v == QLatin1String("space")) e.parity = QSerialPort::SpaceParity;
            else if (v == QLatin1String("mark")) e.parity = QSerialPort::MarkParity;
            else good = false;
        } else if (k == QLatin1String("stopbits")) {
            if (v == QLatin1String("1")) e.stopBits = QSerialPort::OneStop;
            else if (v == QLatin1String("1.5")) e.stopBits = QSerialPort::OneAndHalfStop;
            else if (v == QLatin1String("2")) e.stopBits = QSerialPort::TwoStop;
            else good = false;
        } else if (k == QLatin1String("flow")) {
            if (v == QLatin1String("none")) e.flowControl = QSerialPort::NoFlowControl;
            else if (v == QLatin1String("hardware")) e.flowControl = QSerialPort::HardwareControl;
            else if (v == QLatin1String("software")) e.flowControl = QSerialPort::SoftwareControl;
            else good = false;
        } else {
            return failWith(error, QCoreApplication::translate("VciEndpoint", "\"%1\": unknown serial setting \"%2\" (baud, databits, parity, stopbits, flow)").arg(text, key));
        }
        if (!good)
            return failWith(error, QCoreApplication::translate("VciEndpoint", "\"%1\": %2=%3 is not a valid value").arg(text, key, value));
    }
    return e;
}

QString VciEndpoint::toString() const
{
    if (kind == Kind::Tcp) {
        const QString shown = host.contains(QLatin1Char(':')) ? QStringLiteral("[%1]").arg(host) : host;
        QString url = QStringLiteral("%1://%2:%3").arg(tls ? QStringLiteral("vci+tls") : QStringLiteral("tcp"), shown).arg(port);
        if (!pinnedSha256.isEmpty())
            url += QStringLiteral("?sha256=") + QString(pinnedSha256).remove(QLatin1Char(':'));
        return url;
    }
    static const char *parities[] = {"none", "?", "even", "odd", "space", "mark"};
    const char *stop = stopBits == QSerialPort::TwoStop ? "2" : stopBits == QSerialPort::OneAndHalfStop ? "1.5" : "1";
    const char *flow = flowControl == QSerialPort::HardwareControl ? "hardware" : flowControl == QSerialPort::SoftwareControl ? "software" : "none";
    return QStringLiteral("serial:%1?baud=%2&databits=%3&parity=%4&stopbits=%5&flow=%6")
        .arg(device)
        .arg(baudRate)
        .arg(int(dataBits))
        .arg(QLatin1String(parities[std::min<int>(parity, 5)]), QLatin1String(stop), QLatin1String(flow));
}

} // namespace sortie::vci
