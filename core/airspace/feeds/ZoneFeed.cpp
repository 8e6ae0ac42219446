#include "ZoneFeed.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QLoggingCategory>
#include <QNetworkAccessManager>
#include <QNetworkReply>
#include <QSaveFile>

namespace sortie::airspace {

Q_LOGGING_CATEGORY(lcZoneFeed, "sortie.airspace.feed")

ZoneFeed::ZoneFeed(QString folder, QNetworkAccessManager *network, Limits limits, QObject *parent)
    : QObject(parent)
    , m_folder(std::move(folder))
    , m_ownNetwork(network ? nullptr : std::make_unique<QNetworkAccessManager>())
    , m_network(network ? network : m_ownNetwork.get())
    , m_limits(limits)
{
}

ZoneFeed::~ZoneFeed()
{
    if (m_reply)
        m_reply->abort();
}

QString ZoneFeed::copyPathOf(const QUrl &url) const
{
    const QString suffix = QFileInfo(url.path()).suffix().toLower();
    const bool known = suffix == QLatin1String("json") || suffix == QLatin1String("geojson") || suffix == QLatin1String("kml")
                    || suffix == QLatin1String("plan");
    const QByteArray hash = QCryptographicHash::hash(url.toString(QUrl::FullyEncoded).toUtf8(), QCryptographicHash::Sha1).toHex().left(12);
    QString host = url.host().isEmpty() ? QStringLiteral("feed") : url.host();
    host.replace(QLatin1Char(':'), QLatin1Char('_'));  // an IPv6 address
    return QDir(m_folder).filePath(QStringLiteral("%1-%2.%3").arg(host, QString::fromLatin1(hash), known ? suffix : QStringLiteral("json")));
}

void ZoneFeed::fetch(const QUrl &url)
{
    if (m_reply)
        return fail(url, tr("Another zone feed is being fetched."));
    const QString scheme = url.scheme().toLower();
    if (!url.isValid() || (scheme != QLatin1String("http") && scheme != QLatin1String("https")) || url.host().isEmpty())
        return fail(url, tr("\"%1\" is no web address (http:// or https://).").arg(url.toString()));
    if (m_folder.isEmpty() || !QDir().mkpath(m_folder))
        return fail(url, tr("There is no folder to keep the zone feed in (%1).").arg(m_folder));
    QNetworkRequest request(url);
    request.setAttribute(QNetworkRequest::RedirectPolicyAttribute, QNetworkRequest::NoLessSafeRedirectPolicy);
    request.setTransferTimeout(m_limits.timeoutMs);
    m_body.clear();
    m_reply = m_network->get(request);
    qCInfo(lcZoneFeed).noquote() << "fetching" << url.toString(QUrl::RemoveUserInfo | QUrl::RemoveQuery);
    connect(m_reply, &QNetworkReply::readyRead, this, [this] {
        m_body += m_reply->readAll();
        if (m_body.size() > m_limits.maxBytes) {
            const QUrl url = m_reply->request().url();
            QNetworkReply *reply = m_reply;
            m_reply = nullptr;
            reply->disconnect(this);
            reply->abort();
            reply->deleteLater();
            m_body.clear();
            emit busyChanged();
            fail(url, tr("The zone feed is larger than %1 MiB; it was not kept.").arg(m_limits.maxBytes / (1024 * 1024)));
        }
    });
    connect(m_reply, &QNetworkReply::finished, this, &ZoneFeed::finish);
    emit busyChanged();
}

void ZoneFeed::cancel()
{
    if (m_reply)
        m_reply->abort();  // finished follows, as a failure
}

void ZoneFeed::finish()
{
    QNetworkReply *reply = m_reply;
    if (!reply)
        return;
    m_reply = nullptr;
    reply->deleteLater();
    const QUrl url = reply->request().url();
    m_body += reply->readAll();
    const QByteArray body = std::exchange(m_body, {});
    emit busyChanged();
    const QVariant status = reply->attribute(QNetworkRequest::HttpStatusCodeAttribute);
    if (reply->error() == QNetworkReply::OperationCanceledError && !status.isValid())
        return fail(url, tr("The zone feed's fetch was stopped (cancelled, or no answer for %1 s).").arg(m_limits.timeoutMs / 1000));
    if (status.isValid() && status.toInt() != 200)
        return fail(url, tr("The zone feed's server answered HTTP %1.").arg(status.toInt()));
    if (reply->error() != QNetworkReply::NoError)
        return fail(url, tr("The zone feed cannot be fetched: %1.").arg(reply->errorString()));
    if (body.isEmpty())
        return fail(url, tr("The zone feed's server sent nothing."));
    const QString copy = copyPathOf(url);
    QSaveFile file(copy);
    if (!file.open(QIODevice::WriteOnly) || file.write(body) != body.size() || !file.commit())
        return fail(url, tr("The zone feed cannot be kept in %1: %2.").arg(copy, file.errorString()));
    m_problem.clear();
    emit problemChanged();
    const QDateTime at = QDateTime::currentDateTimeUtc();
    qCInfo(lcZoneFeed).noquote() << body.size() << "bytes kept in" << copy;
    emit fetched(copy, url, at);
}

void ZoneFeed::fail(const QUrl &url, const QString &reason)
{
    qCWarning(lcZoneFeed).noquote() << "zone feed not fetched:" << reason;
    m_problem = reason;
    emit problemChanged();
    emit failed(url, reason);
}

} // namespace sortie::airspace
