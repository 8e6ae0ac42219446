#pragma once

#include "GeoZone.h"
#include "GeoZoneReader.h"
#include "JsonCursor.h"

#include <memory>

namespace sortie::datum {
class Egm96Geoid;
}

// What ED-269 and ED-318 readers share: texts, times, limits and rings. Each fails at its cursor
// (a JsonPathError the reader turns into a left-out feature).
namespace sortie::airspace::ed::reading {

using mission::formats::Json;
using mission::formats::JsonCursor;

// The EGM96 grid, opened on the first WGS-84 limit.
class GeoidAccess
{
public:
    explicit GeoidAccess(QString gridPath);
    ~GeoidAccess();
    // AMSL of an ellipsoidal height at `where`; fails at `c` naming the grid when it cannot.
    double amsl(const JsonCursor &c, const GeoPoint &where, double ellipsoidal);

private:
    QString m_gridPath;
    std::unique_ptr<datum::Egm96Geoid> m_geoid;
    QString m_error;
    bool m_tried = false;
};

// A value the format gives as one, also when written as a list of one ("M" or ["M"]); a longer
// list fails.
JsonCursor single(const JsonCursor &c);
// A text: a string, an ED-318 {text, lang}, or a list of either (the English one, else the first).
QString text(const JsonCursor &c);
QString textOr(const JsonCursor &object, const char *key);
// A list of strings, or one string as a list of one.
QStringList strings(const JsonCursor &object, const char *key);

// ISO 8601 with a date ("2026-06-01T00:00:00Z"; no offset: UTC). Fails unless it is one.
QDateTime dateTime(const JsonCursor &c);
// A time of day, "HH:MM", "HH:MM:SS", "HH:MM:SS.ss", then "Z", an offset ("+01:00") or nothing
// (UTC): seconds from UTC midnight. "24:00" is the end of the day.
int timeOfDay(const JsonCursor &c);
// MON..SUN, ANY: the bit mask of DailyPeriod::days.
std::uint8_t days(const JsonCursor &list);
// One daily period (day[], startTime, endTime).
DailyPeriod dailyPeriod(const JsonCursor &c);

// An applicability period: ED-269's `permanent` (YES / NO, or true / false), start and end
// (ISO 8601; the end after the start), its schedule.
TimePeriod period(const JsonCursor &c);
// A zone authority; its texts plain or per language.
Authority authority(const JsonCursor &c);

// A limit in `uom` ("M" / "FT", either case) over `reference` (AGL, AMSL, WGS84); 99999 or more is
// no limit (nullopt). A lower limit of 0 over the ground is the ground (nullopt).
std::optional<VerticalLimit> limit(const JsonCursor &value, const QString &uom, const JsonCursor &reference, bool upper,
                                   const GeoPoint &where, GeoidAccess &geoid);
// The upper limit is above the lower one where both share a reference; fails at `c` otherwise.
void checkLimits(const JsonCursor &c, const Volume &v);

// [longitude, latitude] (a third value, an altitude, is ignored).
GeoPoint position(const JsonCursor &c);
// GeoJSON polygon rings: repeated vertices dropped, stored open; each ring 3 distinct positions.
Polygon polygon(const JsonCursor &rings);
// Where a volume is, for the geoid: its circle's centre or its first vertex.
GeoPoint anchor(const Volume &v);

// "feature 3 ('LSZH', CH0001)" for a problem; from whatever the JSON has.
QString featureLabel(const Json &properties, size_t index);
// The problem line of a left-out feature.
QString leftOut(const QString &label, const mission::formats::JsonPathError &e);

} // namespace sortie::airspace::ed::reading

namespace sortie::airspace::ed {
// The readers over parsed JSON, and their formats' tops (detection).
bool looksLikeEd269(const mission::formats::Json &root);
bool looksLikeEd318(const mission::formats::Json &root);
mission::Result<GeoZoneFile> readEd269Json(const mission::formats::Json &root, const ReadOptions &options);
mission::Result<GeoZoneFile> readEd318Json(const mission::formats::Json &root, const ReadOptions &options);
} // namespace sortie::airspace::ed
