#pragma once

#include "ElevationSample.h"

#include <QByteArrayView>
#include <QString>

#include <cstdint>
#include <optional>

namespace sortie::terrain {

// Which 1°×1° cell a tile covers: the latitude and longitude of its south-west corner.
struct TileCell
{
    int south = 0;  // -90..89
    int west = 0;   // -180..179
    bool operator==(const TileCell &) const = default;
    int key() const { return (south + 90) * 360 + (west + 180); }
    static TileCell containing(double latitude, double longitude);
};

// "N56E024.hgt" -> {56, 24}; case-insensitive; nullopt for any other name.
std::optional<TileCell> parseHgtName(const QString &fileName);
QString hgtName(TileCell cell);

// One SRTM tile: big-endian int16 metres above the EGM96 geoid on a square grid, row 0 at the north
// edge, column 0 at the west edge, 1201 (3″) or 3601 (1″) samples a side, −32768 = void. The data
// is not copied: the view must outlive the tile (HgtTileSource keeps the file mapped).
class HgtTile
{
public:
    static constexpr int16_t kVoid = -32768;
    // Heights outside this range are not on Earth: a file holding one is not an SRTM tile.
    static constexpr int kLowest = -1000, kHighest = 9000;

    // Checks the size (which gives the resolution) and every value; nullopt with `error` (naming
    // `fileName`) when the data is not a whole, sane tile. Nothing of a rejected tile is used.
    static std::optional<HgtTile> fromData(QByteArrayView data, TileCell cell, const QString &fileName, QString *error);

    TileCell cell() const { return m_cell; }
    int size() const { return m_size; }  // samples a side
    int16_t raw(int row, int column) const
    {
        const auto *p = reinterpret_cast<const unsigned char *>(m_data) + 2 * (size_t(row) * size_t(m_size) + size_t(column));
        return int16_t(uint16_t(p[0]) << 8 | p[1]);
    }
    // Bilinear between the four grid posts around the point; NoData when one with weight is void.
    // The point must be inside the cell (edges included).
    ElevationSample sample(double latitude, double longitude) const;

private:
    HgtTile(const char *data, int size, TileCell cell) : m_data(data), m_size(size), m_cell(cell) {}
    const char *m_data;
    int m_size;
    TileCell m_cell;
};

} // namespace sortie::terrain
