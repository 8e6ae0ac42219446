#pragma once

#include <QDateTime>
#include <QNetworkReply>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QUrl>

#include <memory>

class QNetworkAccessManager;

namespace sortie::airspace {

// What a zone feed's fetch may take.
struct ZoneFeedLimits
{
    qint64 maxBytes = 64 * 1024 * 1024;  // Switzerland's ED-269 file is about 10 MB
    int timeoutMs = 60'000;              // without a byte received
};

// A published zone file (a country's ED-269 or ED-318 feed, any zone file on a web server) fetched
// from its URL into a copy kept for flying offline (docs/airspace.md, "Feeds"). One fetch at a time;
// the body is bounded (a feed is megabytes, not gigabytes) and the copy replaced only whole, so a
// failed fetch leaves the last good copy in place. What the copy holds is read by Airspace as any
// zone file; this class only fetches and keeps.
class ZoneFeed : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool busy READ isBusy NOTIFY busyChanged)
    Q_PROPERTY(QString problem READ problem NOTIFY problemChanged)  // the last fetch's, empty when it worked

public:
    using Limits = ZoneFeedLimits;

    // The copies go into `folder` (created when needed); empty: nothing can be kept, a fetch fails
    // saying so. `network` (not owned) may be null: the feed then has its own.
    explicit ZoneFeed(QString folder, QNetworkAccessManager *network = nullptr, Limits limits = Limits(), QObject *parent = nullptr);
    ~ZoneFeed() override;

    bool isBusy() const { return m_reply != nullptr; }
    QString problem() const { return m_problem; }
    QString folder() const { return m_folder; }
    // Where the copy of `url` is kept: "<host>-<12 hex digits of the URL's SHA-1>.<its extension>"
    // (.json, .geojson, .kml or .plan; .json for anything else).
    QString copyPathOf(const QUrl &url) const;

    // http:// or https:// only; refused (problem, failed) while a fetch runs or for any other URL.
    Q_INVOKABLE void fetch(const QUrl &url);
    Q_INVOKABLE void cancel();

signals:
    void busyChanged();
    void problemChanged();
    void fetched(const QString &copy, const QUrl &url, const QDateTime &fetchedAtUtc);
    void failed(const QUrl &url, const QString &reason);

private:
    void finish();
    void fail(const QUrl &url, const QString &reason);

    QString m_folder;
    std::unique_ptr<QNetworkAccessManager> m_ownNetwork;
    QNetworkAccessManager *m_network;
    Limits m_limits;
    QPointer<QNetworkReply> m_reply;
    QByteArray m_body;
    QString m_problem;
};

} // namespace sortie::airspace
