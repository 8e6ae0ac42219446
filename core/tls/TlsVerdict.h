#pragma once

#include "TlsOptions.h"

#include <QList>
#include <QSslCertificate>
#include <QString>

namespace sortie::tls {

// The one decision on a server's certificate, taken after the TLS handshake and before a byte of the
// protocol (a password, a command) is written. In order:
//   pinned (TlsOptions::pinnedSha256, else the store's pin for the peer): that certificate only;
//   trusted by the system's CA certificates for the host name: accepted;
//   remembered for the peer: the same certificate only (a changed one is refused naming both);
//   otherwise trusted on first use: remembered in the store and shown (firstUse).
struct TlsVerdict
{
    enum class Basis { Refused, Pinned, System, Remembered, FirstUse };

    Basis basis = Basis::Refused;
    QString fingerprint; // the certificate's SHA-256, colon-hex; empty when the server sent none
    QString reason;      // why it was refused, in the operator's words

    bool accepted() const { return basis != Basis::Refused; }
    bool firstUse() const { return basis == Basis::FirstUse; }

    // `peer` is "host:port" as the store keys it, `hostName` what the certificate must name.
    static TlsVerdict judge(const TlsOptions &options, const QString &peer, const QString &hostName,
                            const QList<QSslCertificate> &chain);
};

} // namespace sortie::tls
