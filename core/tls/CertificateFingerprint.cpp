#include "CertificateFingerprint.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QFile>

namespace sortie::tls {
namespace {

QString colonHex(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(':').toUpper());
}

} // namespace

QString sha256Fingerprint(const QSslCertificate &certificate)
{
    if (certificate.isNull())
        return {};
    return colonHex(certificate.digest(QCryptographicHash::Sha256));
}

std::optional<QString> normalizedFingerprint(const QString &text)
{
    QString hex = text.trimmed();
    if (hex.startsWith(QLatin1String("sha256:"), Qt::CaseInsensitive))
        hex = hex.mid(7);
    else if (hex.startsWith(QLatin1String("sha256="), Qt::CaseInsensitive))
        hex = hex.mid(7);
    hex.remove(QLatin1Char(':')).remove(QLatin1Char(' '));
    if (hex.size() != 64)
        return std::nullopt;
    for (const QChar c : std::as_const(hex))
        if (!c.isDigit() && !(c.toLower() >= QLatin1Char('a') && c.toLower() <= QLatin1Char('f')))
            return std::nullopt;
    return colonHex(QByteArray::fromHex(hex.toLatin1()));
}

std::variant<QString, QString> pinFromArgument(const QString &option, const QString &value)
{
    using Outcome = std::variant<QString, QString>;
    if (const auto pin = normalizedFingerprint(value))
        return Outcome(std::in_place_index<0>, *pin);
    if (QFile::exists(value)) {
        QFile file(value);
        const QList<QSslCertificate> certificates = file.open(QIODevice::ReadOnly) ? QSslCertificate::fromData(file.readAll(), QSsl::Pem)
                                                                                   : QList<QSslCertificate>{};
        if (certificates.isEmpty())
            return Outcome(std::in_place_index<1>, QCoreApplication::translate("CertificateFingerprint", "%1: %2 holds no PEM certificate").arg(option, value));
        return Outcome(std::in_place_index<0>, sha256Fingerprint(certificates.first()));
    }
    return Outcome(std::in_place_index<1>,
                   QCoreApplication::translate("CertificateFingerprint", "%1: '%2' is neither a SHA-256 fingerprint (64 hex digits) nor a certificate file").arg(option, value));
}

} // namespace sortie::tls
