#pragma once

#include <QSslConfiguration>
#include <QString>

#include <memory>
#include <optional>

class QObject;
class QTcpServer;

namespace sortie::tls {

// A server's certificate and private key (PEM files, as `openssl req -x509` writes them), for the
// simulator's TLS listeners; nullopt with an error naming the file when one cannot be used.
std::optional<QSslConfiguration> loadServerIdentity(const QString &certificatePath, const QString &keyPath, QString *error);

// A listener: plain TCP without an identity, else one that completes the TLS handshake before it
// hands a connection out (QSslServer: take connections on pendingConnectionAvailable).
std::unique_ptr<QTcpServer> makeListener(const std::optional<QSslConfiguration> &identity, QObject *parent = nullptr);

} // namespace sortie::tls
