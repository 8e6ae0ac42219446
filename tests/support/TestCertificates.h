#pragma once

// Certificates made at test time with the `openssl` command (scripts/install-deps.sh installs it):
// self-signed ones for trust on first use and pinning, and a small CA with a certificate it signed
// for the system-trust path. Header only, on every test's include path (as CommandCatcher.h).
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QString>
#include <QStringList>

#include <optional>

namespace sortie::test {

struct TestIdentity
{
    QString certificate; // PEM file
    QString key;         // PEM file, unencrypted
    QString fingerprint; // SHA-256 as `openssl x509 -fingerprint -sha256` prints it (after "=")
};

class TestCertificates
{
public:
    explicit TestCertificates(QString folder)
        : m_folder(std::move(folder))
    {
    }

    QString error() const { return m_error; }

    // A self-signed certificate for localhost and 127.0.0.1, valid for two days.
    std::optional<TestIdentity> selfSigned(const QString &name)
    {
        TestIdentity id{path(name + QStringLiteral(".crt")), path(name + QStringLiteral(".key")), {}};
        if (!openssl({QStringLiteral("req"), QStringLiteral("-x509"), QStringLiteral("-newkey"), QStringLiteral("rsa:2048"),
                      QStringLiteral("-nodes"), QStringLiteral("-days"), QStringLiteral("2"), QStringLiteral("-subj"),
                      QStringLiteral("/CN=localhost"), QStringLiteral("-addext"), QStringLiteral("subjectAltName=DNS:localhost,IP:127.0.0.1"),
                      QStringLiteral("-keyout"), id.key, QStringLiteral("-out"), id.certificate}))
            return std::nullopt;
        return withFingerprint(id);
    }

    // A CA ("<name>-ca.crt") and a certificate for localhost and 127.0.0.1 it signed.
    std::optional<TestIdentity> signedByCa(const QString &name, QString *caCertificate)
    {
        const QString caKey = path(name + QStringLiteral("-ca.key")), caCrt = path(name + QStringLiteral("-ca.crt")), csr = path(name + QStringLiteral(".csr")), ext = path(name + QStringLiteral(".ext"));
        TestIdentity id{path(name + QStringLiteral(".crt")), path(name + QStringLiteral(".key")), {}};
        QFile extFile(ext);
        if (!extFile.open(QIODevice::WriteOnly))
            return fail(ext + QStringLiteral(": ") + extFile.errorString());
        extFile.write("subjectAltName=DNS:localhost,IP:127.0.0.1\nbasicConstraints=CA:FALSE\n");
        extFile.close();
        if (!openssl({QStringLiteral("req"), QStringLiteral("-x509"), QStringLiteral("-newkey"), QStringLiteral("rsa:2048"), QStringLiteral("-nodes"),
                      QStringLiteral("-days"), QStringLiteral("2"), QStringLiteral("-subj"), QStringLiteral("/CN=Sortie test CA"),
                      QStringLiteral("-keyout"), caKey, QStringLiteral("-out"), caCrt})
            || !openssl({QStringLiteral("req"), QStringLiteral("-newkey"), QStringLiteral("rsa:2048"), QStringLiteral("-nodes"), QStringLiteral("-subj"),
                         QStringLiteral("/CN=localhost"), QStringLiteral("-keyout"), id.key, QStringLiteral("-out"), csr})
            || !openssl({QStringLiteral("x509"), QStringLiteral("-req"), QStringLiteral("-in"), csr, QStringLiteral("-CA"), caCrt,
                         QStringLiteral("-CAkey"), caKey, QStringLiteral("-CAcreateserial"), QStringLiteral("-days"), QStringLiteral("2"),
                         QStringLiteral("-extfile"), ext, QStringLiteral("-out"), id.certificate}))
            return std::nullopt;
        if (caCertificate)
            *caCertificate = caCrt;
        return withFingerprint(id);
    }

private:
    QString path(const QString &file) const { return QDir(m_folder).filePath(file); }

    std::optional<TestIdentity> fail(const QString &message)
    {
        m_error = message;
        return std::nullopt;
    }

    bool openssl(const QStringList &arguments, QByteArray *output = nullptr)
    {
        const QString program = QStandardPaths::findExecutable(QStringLiteral("openssl"));
        if (program.isEmpty()) {
            m_error = QStringLiteral("no openssl command (scripts/install-deps.sh installs it)");
            return false;
        }
        QProcess p;
        p.start(program, arguments);
        if (!p.waitForFinished(60000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
            m_error = QStringLiteral("openssl %1: %2").arg(arguments.join(u' '), QString::fromLocal8Bit(p.readAllStandardError()));
            return false;
        }
        if (output)
            *output = p.readAllStandardOutput();
        return true;
    }

    std::optional<TestIdentity> withFingerprint(TestIdentity id)
    {
        QByteArray out;
        if (!openssl({QStringLiteral("x509"), QStringLiteral("-in"), id.certificate, QStringLiteral("-noout"), QStringLiteral("-fingerprint"), QStringLiteral("-sha256")}, &out))
            return std::nullopt;
        const auto match = QRegularExpression(QStringLiteral("=([0-9A-F:]{95})")).match(QString::fromLatin1(out));
        if (!match.hasMatch())
            return fail(QStringLiteral("openssl printed no SHA-256 fingerprint: %1").arg(QString::fromLatin1(out)));
        id.fingerprint = match.captured(1);
        return id;
    }

    QString m_folder;
    QString m_error;
};

} // namespace sortie::test
