#include "TileUrlTemplate.h"

#include <QCoreApplication>

namespace sortie::maptiles {

namespace {

// Query item names that carry a key, as tile services name them (Thunderforest apikey, MapTiler key,
// Mapbox access_token, Azure subscription-key, HERE apiKey, signed URLs' signature), compared in lower case.
bool namesASecret(const QString &name)
{
    static const QStringList names{QStringLiteral("key"), QStringLiteral("apikey"), QStringLiteral("api_key"), QStringLiteral("api-key"),
                                   QStringLiteral("access_token"), QStringLiteral("accesstoken"), QStringLiteral("token"),
                                   QStringLiteral("auth"), QStringLiteral("password"), QStringLiteral("secret"),
                                   QStringLiteral("client_secret"), QStringLiteral("subscription-key"), QStringLiteral("signature"),
                                   QStringLiteral("sig")};
    return names.contains(name.toLower());
}

} // namespace

TileUrlTemplate::TileUrlTemplate(QString pattern, QString subdomains)
    : m_pattern(std::move(pattern))
    , m_subdomains(std::move(subdomains))
{
}

QString TileUrlTemplate::validate(const QString &pattern)
{
    if (pattern.trimmed().isEmpty())
        return QCoreApplication::translate("TileUrlTemplate", "No tile URL template is set.");
    QString sample = pattern;
    for (const char *field : {"{z}", "{x}", "{y}", "{-y}"})
        sample.replace(QLatin1String(field), QLatin1String("0"));
    sample.replace(QLatin1String("{s}"), QLatin1String("a"));
    const QUrl url(sample, QUrl::StrictMode);
    if (!url.isValid())
        return QCoreApplication::translate("TileUrlTemplate", "The tile URL template is not a valid URL: %1").arg(url.errorString());
    const QString scheme = url.scheme().toLower();
    if (scheme != QLatin1String("http") && scheme != QLatin1String("https") && scheme != QLatin1String("file"))
        return QCoreApplication::translate("TileUrlTemplate", "The tile URL template must start with http://, https:// or file://.");
    const bool hasY = pattern.contains(QLatin1String("{y}")) || pattern.contains(QLatin1String("{-y}"));
    if (!pattern.contains(QLatin1String("{z}")) || !pattern.contains(QLatin1String("{x}")) || !hasY)
        return QCoreApplication::translate("TileUrlTemplate", "The tile URL template needs {z}, {x} and {y} (or {-y}).");
    return {};
}

QUrl TileUrlTemplate::url(const TileId &tile) const
{
    if (!isUsable() || !tile.isValid())
        return {};
    QString text = m_pattern;
    text.replace(QLatin1String("{z}"), QString::number(tile.z));
    text.replace(QLatin1String("{x}"), QString::number(tile.x));
    text.replace(QLatin1String("{y}"), QString::number(tile.y));
    text.replace(QLatin1String("{-y}"), QString::number(tile.tmsRow()));
    if (!m_subdomains.isEmpty())
        text.replace(QLatin1String("{s}"), m_subdomains.at((tile.x + tile.y) % m_subdomains.size()));
    return QUrl(text, QUrl::TolerantMode);
}

QStringList TileUrlTemplate::secrets() const
{
    QStringList found;
    const qsizetype query = m_pattern.indexOf(QLatin1Char('?'));
    if (query >= 0) {
        QString items = m_pattern.mid(query + 1);
        items = items.left(items.indexOf(QLatin1Char('#')) < 0 ? items.size() : items.indexOf(QLatin1Char('#')));
        for (const QString &item : items.split(QLatin1Char('&'), Qt::SkipEmptyParts)) {
            const qsizetype eq = item.indexOf(QLatin1Char('='));
            if (eq <= 0)
                continue;
            const QString value = item.mid(eq + 1);
            if (namesASecret(QUrl::fromPercentEncoding(item.left(eq).toUtf8())) && !value.isEmpty() && !value.startsWith(QLatin1Char('{')))
                found << value;
        }
    }
    // https://user:password@host/...
    const qsizetype scheme = m_pattern.indexOf(QLatin1String("://"));
    if (scheme > 0) {
        const qsizetype at = m_pattern.indexOf(QLatin1Char('@'), scheme + 3), slash = m_pattern.indexOf(QLatin1Char('/'), scheme + 3);
        const qsizetype colon = m_pattern.indexOf(QLatin1Char(':'), scheme + 3);
        if (at > 0 && (slash < 0 || at < slash) && colon > 0 && colon < at && at - colon > 1)
            found << m_pattern.mid(colon + 1, at - colon - 1);
    }
    return found;
}

QString TileUrlTemplate::redacted(const QString &text) const
{
    QString out = text;
    for (const QString &secret : secrets()) {
        if (secret.size() < 4)
            continue;  // "key=x" is no secret, and replacing every "x" would garble the text
        const QString decoded = QUrl::fromPercentEncoding(secret.toUtf8());
        for (const QString &form : {secret, decoded, QString::fromLatin1(QUrl::toPercentEncoding(decoded))})
            if (!form.isEmpty())
                out.replace(form, QStringLiteral("•••"));
    }
    return out;
}

QString TileUrlTemplate::host() const
{
    return url({0, 0, 0}).host();
}

} // namespace sortie::maptiles
