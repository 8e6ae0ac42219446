#pragma once

#include <QColor>

namespace sortie::ui {

// Colours of the offline base map and graticule, in a light and a dark variant so the map
// follows the system palette.
struct MapPalette
{
    QColor sea;
    QColor land;
    QColor coast;
    QColor graticule;
    QColor label;

    static MapPalette light()
    {
        return {QColor(0xa9, 0xcf, 0xe3), QColor(0xef, 0xeb, 0xe0), QColor(0x7c, 0x94, 0xa6),
                QColor(40, 60, 90, 70), QColor(0x33, 0x44, 0x55)};
    }
    static MapPalette dark()
    {
        return {QColor(0x16, 0x26, 0x36), QColor(0x3a, 0x40, 0x45), QColor(0x6a, 0x7d, 0x8c),
                QColor(200, 220, 240, 60), QColor(0xc8, 0xd2, 0xdc)};
    }
    bool operator==(const MapPalette &) const = default;
};

} // namespace sortie::ui
