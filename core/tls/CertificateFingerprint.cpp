#include "CertificateFingerprint.h"

#include <QCryptographicHash>

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

} // namespace sortie::tls
