#pragma once

#include "Zone.h"

#include <QString>
#include <QStringList>

#include <google/protobuf/repeated_ptr_field.h>

#include <optional>
#include <vector>

namespace com::ugcs::ucs::proto {
class NoFlightZone;
}

namespace sortie::airspace {

namespace pb = com::ugcs::ucs::proto;

// The UgCS server's no-fly zones (NoFlightZone: a Prism or a ConeFrustum, NT_CUSTOM or
// NT_AERODROME) as zones, and custom zones back. Wire facts: latitudes and longitudes in radians,
// altitudes and radii in metres; altitudeType AT_WGS84 is AMSL, AT_AGL above the ground under the
// point. A volume starts at baseAltitude and is `height` metres tall: floor = baseAltitude,
// ceiling = baseAltitude + height, in the volume's altitudeType (no height: unlimited). A prism
// with no baseAltitude, or one at or below 0 m AGL, starts from the ground (no floor). A cone
// frustum's baseRadius is its radius at the floor, topRadius at the ceiling; equal radii make a
// circle. A server zone is always an exclusion zone.
namespace NfzConversion {

// The zone, or nullopt with `why` saying what is wrong ("has no volume", "point 3 is not a
// position") so the caller can name it. The zone keeps the object's id and version (serverId).
std::optional<Zone> toZone(const pb::NoFlightZone &nfz, QString *why);

// The zone as a custom NoFlightZone to create (no serverId) or update (with it). `before`, the
// object as the server last sent it, keeps the fields Sortie does not model (tag, sealed). Refused
// with `why`: an inclusion zone, an aerodrome zone, several polygons or holes, a floor and a
// ceiling in different references, heights above home, a ceiling without a floor in AMSL.
std::optional<pb::NoFlightZone> toNfz(const Zone &zone, const pb::NoFlightZone *before, QString *why);

// What a zone is called in messages: its name, else "NoFlightZone <id>".
QString nameOf(const pb::NoFlightZone &nfz);

// The zones of a server answer; each one that cannot be converted is left out with a line naming
// it and the reason ("NoFlightZone 12 ('Pier') was left out: ...").
std::vector<Zone> toZones(const google::protobuf::RepeatedPtrField<pb::NoFlightZone> &zones, QStringList *problems);

} // namespace NfzConversion

} // namespace sortie::airspace
