// Which of the two formats bytes are, by content (GeoZoneReader.h).
#include "EdReading.h"

namespace sortie::airspace::ed {

using mission::formats::Json;

std::optional<Format> detectGeoZoneFormat(const QByteArray &data)
{
    const mission::Result<Json> parsed = mission::formats::parseJson(data);
    if (!parsed)
        return std::nullopt;
    if (looksLikeEd269(parsed.value()))
        return Format::Ed269;
    if (looksLikeEd318(parsed.value()))
        return Format::Ed318;
    return std::nullopt;
}

std::optional<mission::Result<GeoZoneFile>> readGeoZones(const QByteArray &data, const ReadOptions &options)
{
    // A cheap look first: neither format is anything but a JSON object (after a UTF-8 byte order mark).
    const qsizetype bom = data.startsWith("\xEF\xBB\xBF") ? 3 : 0;
    const qsizetype first = data.indexOf('{', bom);
    if (first < 0 || !data.mid(bom, first - bom).trimmed().isEmpty())
        return std::nullopt;
    const mission::Result<Json> parsed = mission::formats::parseJson(data);
    if (!parsed)
        return std::nullopt;
    if (looksLikeEd269(parsed.value()))
        return readEd269Json(parsed.value(), options);
    if (looksLikeEd318(parsed.value()))
        return readEd318Json(parsed.value(), options);
    return std::nullopt;
}

} // namespace sortie::airspace::ed
