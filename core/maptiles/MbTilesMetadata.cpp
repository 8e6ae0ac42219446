#include "MbTilesMetadata.h"

#include <QCoreApplication>

#include <cmath>

namespace sortie::maptiles {

namespace {

std::optional<int> zoomLevel(const QString &key, const QString &value, QStringList &problems)
{
    bool ok = false;
    const int zoom = value.trimmed().toInt(&ok);
    if (ok && zoom >= 0 && zoom <= 30)
        return zoom;
    problems.append(QCoreApplication::translate("MbTilesMetadata", "%1: '%2' is not a zoom level (0 to 30).").arg(key, value.left(40)));
    return std::nullopt;
}

std::optional<GeoBounds> boundsOf(const QString &value, QStringList &problems)
{
    const QStringList parts = value.split(QLatin1Char(','));
    double numbers[4] = {};
    bool ok = parts.size() == 4;
    for (int i = 0; ok && i < 4; ++i) {
        numbers[i] = parts.at(i).trimmed().toDouble(&ok);
        ok = ok && std::isfinite(numbers[i]);
    }
    // MBTiles writes left, bottom, right, top.
    const GeoBounds bounds{numbers[1], numbers[0], numbers[3], numbers[2]};
    if (ok && bounds.isValid())
        return bounds;
    problems.append(QCoreApplication::translate("MbTilesMetadata", "bounds: '%1' is not west,south,east,north in degrees.").arg(value.left(80)));
    return std::nullopt;
}
} // namespace

MbTilesMetadata MbTilesMetadata::fromPairs(const QList<QPair<QString, QString>> &pairs)
{
    MbTilesMetadata m;
    for (const auto &[key, value] : pairs) {
        if (key == QLatin1String("name"))
            m.name = value;
        else if (key == QLatin1String("attribution"))
            m.attribution = value;
        else if (key == QLatin1String("description"))
            m.description = value;
        else if (key == QLatin1String("format"))
            m.format = value.trimmed().toLower();
        else if (key == QLatin1String("version"))
            m.version = value;
        else if (key == QLatin1String("minzoom"))
            m.minZoom = zoomLevel(key, value, m.problems);
        else if (key == QLatin1String("maxzoom"))
            m.maxZoom = zoomLevel(key, value, m.problems);
        else if (key == QLatin1String("bounds"))
            m.bounds = boundsOf(value, m.problems);
        else
            m.others.append({key, value});
    }
    if (m.minZoom && m.maxZoom && *m.minZoom > *m.maxZoom) {
        m.problems.append(QCoreApplication::translate("MbTilesMetadata", "minzoom %1 is above maxzoom %2.").arg(*m.minZoom).arg(*m.maxZoom));
        m.minZoom.reset();
        m.maxZoom.reset();
    }
    return m;
}

QList<QPair<QString, QString>> MbTilesMetadata::toPairs() const
{
    QList<QPair<QString, QString>> pairs;
    const auto add = [&](const char *key, const QString &value) {
        if (!value.isEmpty())
            pairs.append({QString::fromLatin1(key), value});
    };
    add("name", name);
    add("attribution", attribution);
    add("description", description);
    add("format", format);
    add("version", version);
    if (minZoom)
        add("minzoom", QString::number(*minZoom));
    if (maxZoom)
        add("maxzoom", QString::number(*maxZoom));
    if (bounds)
        add("bounds", QStringLiteral("%1,%2,%3,%4").arg(bounds->west, 0, 'g', 17).arg(bounds->south, 0, 'g', 17)
                          .arg(bounds->east, 0, 'g', 17).arg(bounds->north, 0, 'g', 17));
    pairs.append(others);
    return pairs;
}

} // namespace sortie::maptiles
