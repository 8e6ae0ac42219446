#pragma once

#include "TileId.h"

#include <QString>
#include <QStringList>
#include <QUrl>

namespace sortie::maptiles {

// A web tile server's address pattern, such as "https://tile.example.org/{z}/{x}/{y}.png":
// {z}, {x} and {y} are replaced per tile, {-y} counts rows from the south, {s} picks one of the
// subdomains. The map's web source and the prefetch job both expand it here.
class TileUrlTemplate
{
public:
    explicit TileUrlTemplate(QString pattern = {}, QString subdomains = QStringLiteral("abc"));

    QString pattern() const { return m_pattern; }
    QString subdomains() const { return m_subdomains; }
    // Why the pattern cannot work, in the operator's words; empty when it can.
    QString problem() const { return validate(m_pattern); }
    bool isUsable() const { return problem().isEmpty(); }
    // The URL of one tile, or an empty URL when the pattern is not usable.
    QUrl url(const TileId &tile) const;
    // The server's host name (the first subdomain's), for names and file names.
    QString host() const;

    // The secrets in the pattern: the values of its query items named as keys are (apikey, key,
    // access_token, token, …) and a password in its user part. What is shown or logged about the
    // server (an error from Qt's network stack quotes the whole URL) goes through redacted().
    QStringList secrets() const;
    // `text` with every secret of the pattern, as written or percent-encoded, replaced by "•••".
    QString redacted(const QString &text) const;

    static QString validate(const QString &pattern);

private:
    QString m_pattern;
    QString m_subdomains;
};

} // namespace sortie::maptiles
