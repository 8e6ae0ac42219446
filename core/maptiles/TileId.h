#pragma once

#include <QString>

#include <cstdint>

namespace sortie::maptiles {

// One XYZ tile: zoom, column (from the antimeridian eastwards) and row (from the north), as web
// tile servers count. MBTiles counts rows from the south (TMS): tmsRow() converts.
struct TileId
{
    int z = 0;
    int x = 0;
    int y = 0;

    bool isValid() const { return z >= 0 && z <= 30 && x >= 0 && y >= 0 && x < (1 << z) && y < (1 << z); }
    int tmsRow() const { return (1 << z) - 1 - y; }
    quint64 packed() const { return (quint64(z) << 58) | (quint64(x) << 29) | quint64(y); }
    QString toString() const { return QStringLiteral("%1/%2/%3").arg(z).arg(x).arg(y); }
    bool operator==(const TileId &other) const = default;
};

} // namespace sortie::maptiles
