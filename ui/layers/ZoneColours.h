#pragma once

#include "GeoZone.h"
#include "MapPalette.h"
#include "Zone.h"

#include <QColor>

#include <optional>

namespace sortie::ui {

// A zone's colour on the map, on the profile and where the route crosses it: a geographical zone's
// by its restriction (prohibited red, authorisation amber, conditions yellow, information blue), any
// other by its kind (exclusion red, inclusion green).
QColor zoneColour(const MapPalette &palette, airspace::ZoneKind kind, std::optional<airspace::ed::Restriction> restriction);
QColor zoneColour(const MapPalette &palette, const airspace::Zone &zone);
// Whether the zone keeps the flight out (hatched): an exclusion zone that is no geographical zone
// with conditions or information only.
bool keepsOut(airspace::ZoneKind kind, std::optional<airspace::ed::Restriction> restriction);

} // namespace sortie::ui
