#pragma once

#include <QSerialPort>
#include <QString>

#include <optional>

namespace sortie::vci {

// Where a vehicle is: "tcp://host:port", "vci+tls://host:port" (TLS, for a vehicle across a network;
// "?sha256=FINGERPRINT" pins its certificate, else TlsVerdict's rules apply) or a serial line,
// "serial:/dev/ttyUSB0?baud=57600&databits=8&parity=none&stopbits=1&flow=none" (all settings optional:
// 115200 8N1 without flow control by default; parity none|even|odd|space|mark; stopbits 1|1.5|2;
// flow none|hardware|software). "serial:///dev/ttyUSB0" is accepted too.
struct VciEndpoint
{
    enum class Kind { Tcp, Serial };

    Kind kind = Kind::Tcp;
    QString host;
    quint16 port = 0;
    bool tls = false;       // Tcp over TLS (vci+tls://)
    QString pinnedSha256;   // vci+tls://...?sha256=: the only certificate accepted, colon-hex
    QString device;
    qint32 baudRate = 115200;
    QSerialPort::DataBits dataBits = QSerialPort::Data8;
    QSerialPort::Parity parity = QSerialPort::NoParity;
    QSerialPort::StopBits stopBits = QSerialPort::OneStop;
    QSerialPort::FlowControl flowControl = QSerialPort::NoFlowControl;

    // nullopt and an operator-readable `error` when the URL is not one of the forms above.
    static std::optional<VciEndpoint> parse(const QString &url, QString *error = nullptr);
    QString toString() const;
};

} // namespace sortie::vci
