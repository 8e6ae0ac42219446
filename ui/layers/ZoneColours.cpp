#include "ZoneColours.h"

namespace sortie::ui {

QColor zoneColour(const MapPalette &palette, airspace::ZoneKind kind, std::optional<airspace::ed::Restriction> restriction)
{
    if (restriction) {
        switch (*restriction) {
        case airspace::ed::Restriction::Prohibited: return palette.exclusion;
        case airspace::ed::Restriction::ReqAuthorisation: return palette.authorisation;
        case airspace::ed::Restriction::Conditional: return palette.conditional;
        case airspace::ed::Restriction::NoRestriction: return palette.information;
        }
    }
    return kind == airspace::ZoneKind::Exclusion ? palette.exclusion : palette.inclusion;
}

QColor zoneColour(const MapPalette &palette, const airspace::Zone &zone)
{
    return zoneColour(palette, zone.kind, zone.geoZone ? std::optional(zone.geoZone->restriction) : std::nullopt);
}

bool keepsOut(airspace::ZoneKind kind, std::optional<airspace::ed::Restriction> restriction)
{
    return kind == airspace::ZoneKind::Exclusion
        && (!restriction || *restriction == airspace::ed::Restriction::Prohibited || *restriction == airspace::ed::Restriction::ReqAuthorisation);
}

} // namespace sortie::ui
