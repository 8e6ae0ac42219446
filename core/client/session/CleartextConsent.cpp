#include "CleartextConsent.h"

#include <QSettings>
#include <QUrl>

namespace sortie::client {
namespace {

QString keyOf(const ServerAddress &address)
{
    return QStringLiteral("security/cleartextAllowed/") + QString::fromLatin1(QUrl::toPercentEncoding(address.peer().toLower()));
}

} // namespace

CleartextConsent::CleartextConsent(QSettings *settings)
    : m_settings(settings)
{
}

bool CleartextConsent::mustAsk(const ServerAddress &address) const
{
    return !address.tls && !address.isLoopback() && !allowed(address);
}

bool CleartextConsent::allowed(const ServerAddress &address) const
{
    return m_settings && m_settings->value(keyOf(address)).toBool();
}

void CleartextConsent::allow(const ServerAddress &address)
{
    if (m_settings)
        m_settings->setValue(keyOf(address), true);
}

} // namespace sortie::client
