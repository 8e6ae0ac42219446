#pragma once

#include <QSslCertificate>
#include <QString>

#include <optional>
#include <variant>

namespace sortie::tls {

// A certificate's SHA-256 fingerprint as operators compare them: 32 bytes in upper-case hex pairs
// joined by colons ("3A:F0:...", what `openssl x509 -fingerprint -sha256` prints after its "=").
QString sha256Fingerprint(const QSslCertificate &certificate);

// A fingerprint as typed or pasted ("sha256:3af0...", "3A F0 ...", "3A:F0:...") in the form above,
// or nullopt when it is not 64 hex digits.
std::optional<QString> normalizedFingerprint(const QString &text);

// A pin as a command line gives it (--server-pin): a SHA-256 fingerprint, or the path of a PEM file
// whose first certificate is the one the server must show. The fingerprint, or an error in words
// naming the option.
std::variant<QString, QString> pinFromArgument(const QString &option, const QString &value);

} // namespace sortie::tls
