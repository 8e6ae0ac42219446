#include "HgtTile.h"

#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <QCoreApplication>

namespace sortie::terrain {

TileCell TileCell::containing(double latitude, double longitude)
{
    int south = int(std::floor(latitude)), west = int(std::floor(longitude));
    // The north pole and the antimeridian's east side belong to the last cell.
    south = std::clamp(south, -90, 89);
    if (west >= 180)
        west -= 360;
    west = std::clamp(west, -180, 179);
    return {south, west};
}

std::optional<TileCell> parseHgtName(const QString &fileName)
{
    static const QRegularExpression re(QStringLiteral("^([NS])(\\d{2})([EW])(\\d{3})\\.hgt$"),
                                       QRegularExpression::CaseInsensitiveOption);
    const auto m = re.match(fileName);
    if (!m.hasMatch())
        return std::nullopt;
    int lat = m.captured(2).toInt(), lon = m.captured(4).toInt();
    if (m.captured(1).compare(QLatin1String("S"), Qt::CaseInsensitive) == 0)
        lat = -lat;
    if (m.captured(3).compare(QLatin1String("W"), Qt::CaseInsensitive) == 0)
        lon = -lon;
    if (lat < -90 || lat > 89 || lon < -180 || lon > 179)
        return std::nullopt;
    return TileCell{lat, lon};
}

QString hgtName(TileCell cell)
{
    return QStringLiteral("%1%2%3%4.hgt")
        .arg(cell.south < 0 ? QLatin1Char('S') : QLatin1Char('N'))
        .arg(std::abs(cell.south), 2, 10, QLatin1Char('0'))
        .arg(cell.west < 0 ? QLatin1Char('W') : QLatin1Char('E'))
        .arg(std::abs(cell.west), 3, 10, QLatin1Char('0'));
}

std::optional<HgtTile> HgtTile::fromData(QByteArrayView data, TileCell cell, const QString &fileName, QString *error)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(fileName, why);
        return std::nullopt;
    };
    int size = 0;
    if (data.size() == qsizetype(2) * 1201 * 1201)
        size = 1201;
    else if (data.size() == qsizetype(2) * 3601 * 3601)
        size = 3601;
    else
        return fail(QCoreApplication::translate("HgtTile", "%1 bytes is not an SRTM tile (2884802 bytes for 3″ 1201×1201, 25934402 for 1″ 3601×3601); "
                                   "the file is truncated or not a .hgt tile")
                        .arg(data.size()));
    HgtTile tile(data.data(), size, cell);
    for (int r = 0; r < size; ++r) {
        for (int c = 0; c < size; ++c) {
            const int v = tile.raw(r, c);
            if (v != kVoid && (v < kLowest || v > kHighest))
                return fail(QCoreApplication::translate("HgtTile", "height %1 m at row %2, column %3 is not a terrain height; the file is corrupt")
                                .arg(v).arg(r).arg(c));
        }
    }
    return tile;
}

ElevationSample HgtTile::sample(double latitude, double longitude) const
{
    const double span = m_size - 1;
    double y = (m_cell.south + 1 - latitude) * span;  // rows grow southwards
    double x = (longitude - m_cell.west) * span;
    // A point on a post (to rounding) is that post: a void beside it has no weight.
    if (std::abs(y - std::round(y)) < 1e-6)
        y = std::round(y);
    if (std::abs(x - std::round(x)) < 1e-6)
        x = std::round(x);
    if (!(y >= -1e-9 && y <= span + 1e-9 && x >= -1e-9 && x <= span + 1e-9))
        return ElevationSample::noData();
    const int r0 = std::clamp(int(std::floor(y)), 0, m_size - 2);
    const int c0 = std::clamp(int(std::floor(x)), 0, m_size - 2);
    const double fy = std::clamp(y - r0, 0.0, 1.0), fx = std::clamp(x - c0, 0.0, 1.0);
    const double w[4] = {(1 - fy) * (1 - fx), (1 - fy) * fx, fy * (1 - fx), fy * fx};
    const int16_t h[4] = {raw(r0, c0), raw(r0, c0 + 1), raw(r0 + 1, c0), raw(r0 + 1, c0 + 1)};
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        if (w[i] == 0.0)
            continue;
        if (h[i] == kVoid)
            return ElevationSample::noData();  // never interpolate across a void
        sum += w[i] * h[i];
    }
    return ElevationSample::value(sum);
}

} // namespace sortie::terrain
