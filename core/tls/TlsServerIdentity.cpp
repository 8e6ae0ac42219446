#include "TlsServerIdentity.h"

#include <QCoreApplication>
#include <QFile>
#include <QSslKey>
#include <QSslServer>
#include <QSslSocket>

namespace sortie::tls {

std::optional<QSslConfiguration> loadServerIdentity(const QString &certificatePath, const QString &keyPath, QString *error)
{
    const auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return std::nullopt;
    };
    if (!QSslSocket::supportsSsl())
        return fail(QCoreApplication::translate("TlsServerIdentity", "this Qt has no TLS backend (%1)").arg(QSslSocket::activeBackend()));
    QFile certFile(certificatePath);
    if (!certFile.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("%1: %2").arg(certificatePath, certFile.errorString()));
    const auto chain = QSslCertificate::fromData(certFile.readAll(), QSsl::Pem);
    if (chain.isEmpty() || chain.first().isNull())
        return fail(QCoreApplication::translate("TlsServerIdentity", "%1 holds no PEM certificate").arg(certificatePath));
    QFile keyFile(keyPath);
    if (!keyFile.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("%1: %2").arg(keyPath, keyFile.errorString()));
    const QByteArray keyPem = keyFile.readAll();
    QSslKey key(keyPem, QSsl::Rsa, QSsl::Pem);
    if (key.isNull())
        key = QSslKey(keyPem, QSsl::Ec, QSsl::Pem);
    if (key.isNull())
        return fail(QCoreApplication::translate("TlsServerIdentity", "%1 holds no unencrypted PEM RSA or EC private key").arg(keyPath));
    QSslConfiguration config = QSslConfiguration::defaultConfiguration();
    config.setLocalCertificateChain(chain);
    config.setPrivateKey(key);
    config.setPeerVerifyMode(QSslSocket::VerifyNone); // clients are not asked for a certificate
    return config;
}

std::unique_ptr<QTcpServer> makeListener(const std::optional<QSslConfiguration> &identity, QObject *parent)
{
    if (!identity)
        return std::make_unique<QTcpServer>(parent);
    auto server = std::make_unique<QSslServer>(parent);
    server->setSslConfiguration(*identity);
    return server;
}

} // namespace sortie::tls
