#pragma once

#include <QColor>

#include <algorithm>
#include <iterator>

namespace sortie::client {

// The colour of the vehicle in a fleet's row: the same in every layer, plot and list that shows it.
// Decided here, below the UI, because the fleet's route list (FleetRoutes) hands it to the views too.
inline QColor vehicleColor(int row)
{
    static constexpr QRgb kColors[] = {0xd81b60, 0x8e24aa, 0x00897b, 0xf4511e, 0x3949ab,
                                       0x7cb342, 0x6d4c41, 0x00acc1, 0xc0ca33, 0x5e35b1};
    return QColor::fromRgb(kColors[std::max(0, row) % int(std::size(kColors))]);
}

} // namespace sortie::client
