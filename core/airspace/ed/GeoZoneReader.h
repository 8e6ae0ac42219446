#pragma once

#include "GeoZone.h"
#include "MissionError.h"

#include <QByteArray>

#include <optional>

namespace sortie::airspace::ed {

struct ReadOptions
{
    // The EGM96 grid WGS-84 (ellipsoidal) limits are converted through; empty: Debian's
    // (proj-data). Opened only when a file has such a limit; missing, those features are left out.
    QString geoidGrid;
};

// The format of ED data, by content: ED-269 is a JSON object whose `features` are zones with a
// `restriction` and a list `geometry`; ED-318 a GeoJSON FeatureCollection whose features'
// properties carry a zone `identifier` with its `zoneAuthority` or `variant`. nullopt for
// anything else (not JSON, other GeoJSON): another reader's.
std::optional<Format> detectGeoZoneFormat(const QByteArray &data);

// Reads one format. Not JSON, or not that format's top level: an error (line, or JSON path). A
// feature that cannot be used (a shape, a limit, a time the format does not allow) is left out,
// named by its place, identifier and the reason; the rest load.
mission::Result<GeoZoneFile> readEd269(const QByteArray &data, const ReadOptions &options = {});
mission::Result<GeoZoneFile> readEd318(const QByteArray &data, const ReadOptions &options = {});

// Either, by content; nullopt when the data is neither.
std::optional<mission::Result<GeoZoneFile>> readGeoZones(const QByteArray &data, const ReadOptions &options = {});

} // namespace sortie::airspace::ed
