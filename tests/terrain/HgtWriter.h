#pragma once

// Writes SRTM .hgt tiles for the tests: big-endian int16, row 0 at the north edge.
#include <QByteArray>
#include <QFile>
#include <QString>

#include <cstdint>
#include <functional>

namespace sortie::terrain::test {

// height(row, column) for every post of a size×size tile.
inline QByteArray hgtBytes(int size, const std::function<int(int, int)> &height)
{
    QByteArray out(qsizetype(size) * size * 2, Qt::Uninitialized);
    auto *p = reinterpret_cast<unsigned char *>(out.data());
    for (int r = 0; r < size; ++r)
        for (int c = 0; c < size; ++c) {
            const auto v = uint16_t(int16_t(height(r, c)));
            *p++ = uchar(v >> 8);
            *p++ = uchar(v & 0xff);
        }
    return out;
}

inline bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

inline bool writeHgt(const QString &path, int size, const std::function<int(int, int)> &height)
{
    return writeFile(path, hgtBytes(size, height));
}

} // namespace sortie::terrain::test
