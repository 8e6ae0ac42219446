#pragma once

#include <QHashFunctions>
#include <QMetaType>
#include <QString>

#include <cstdint>

namespace sortie::ui {

// One XYZ tile: zoom, column (x, from the antimeridian eastwards) and row (y, from the north).
struct TileKey
{
    int z = 0;
    int x = 0;
    int y = 0;

    bool isValid() const { return z >= 0 && z <= 30 && x >= 0 && y >= 0 && x < (1 << z) && y < (1 << z); }
    quint64 packed() const { return (quint64(z) << 58) | (quint64(x) << 29) | quint64(y); }
    // The tile one level up that contains this one.
    TileKey parent() const { return {z - 1, x / 2, y / 2}; }
    QString toString() const { return QStringLiteral("%1/%2/%3").arg(z).arg(x).arg(y); }
    bool operator==(const TileKey &other) const = default;
};

inline size_t qHash(const TileKey &key, size_t seed = 0)
{
    return ::qHash(key.packed(), seed);
}

} // namespace sortie::ui

Q_DECLARE_METATYPE(sortie::ui::TileKey)
