#include "CertificateStore.h"

#include "CertificateFingerprint.h"

#include <QSettings>
#include <QUrl>

namespace sortie::tls {
namespace {

// host:port as one settings key: a colon or bracket means something to some settings formats.
QString keyOf(const char *group, const QString &peer)
{
    return QStringLiteral("tls/%1/%2").arg(QLatin1String(group), QString::fromLatin1(QUrl::toPercentEncoding(peer.toLower())));
}

} // namespace

CertificateStore::CertificateStore(QSettings *settings)
    : m_settings(settings)
{
}

std::optional<QString> CertificateStore::read(const QString &key) const
{
    if (!m_settings)
        return std::nullopt;
    return normalizedFingerprint(m_settings->value(key).toString());
}

std::optional<QString> CertificateStore::pinned(const QString &peer) const
{
    return read(keyOf("pinned", peer));
}

bool CertificateStore::pin(const QString &peer, const QString &fingerprint)
{
    const auto normal = normalizedFingerprint(fingerprint);
    if (!normal || !m_settings)
        return false;
    m_settings->setValue(keyOf("pinned", peer), *normal);
    return true;
}

void CertificateStore::unpin(const QString &peer)
{
    if (m_settings)
        m_settings->remove(keyOf("pinned", peer));
}

std::optional<QString> CertificateStore::remembered(const QString &peer) const
{
    return read(keyOf("remembered", peer));
}

void CertificateStore::remember(const QString &peer, const QString &fingerprint)
{
    if (m_settings)
        m_settings->setValue(keyOf("remembered", peer), fingerprint);
}

void CertificateStore::forget(const QString &peer)
{
    if (m_settings)
        m_settings->remove(keyOf("remembered", peer));
}

} // namespace sortie::tls
