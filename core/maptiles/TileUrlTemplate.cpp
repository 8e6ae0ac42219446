#include "TileUrlTemplate.h"

#include <QCoreApplication>

namespace sortie::maptiles {

namespace {
}

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

QString TileUrlTemplate::host() const
{
    return url({0, 0, 0}).host();
}

} // namespace sortie::maptiles
