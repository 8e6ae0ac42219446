#pragma once

#include "GeoPoint.h"

#include <QDateTime>
#include <QString>
#include <QStringList>
#include <QTimeZone>

#include <cstdint>
#include <optional>
#include <vector>

// UAS geographical zones as the law publishes them (EU 2019/947 Art. 15; EUROCAE ED-269 and its
// successor ED-318; docs/airspace.md, "UAS geographical zones"): what a zone restricts, when, where,
// and who to ask. The shapes and limits are plain values; core/airspace turns each volume into a
// zone it checks.
namespace sortie::airspace::ed {

using mission::GeoPoint;

// What the zone means for a flight inside it.
enum class Restriction { Prohibited, ReqAuthorisation, Conditional, NoRestriction };
// ED-269's spelling ("PROHIBITED", "REQ_AUTHORISATION", "CONDITIONAL", "NO_RESTRICTION").
QString restrictionName(Restriction restriction);
// In the operator's words: "Prohibited", "Authorisation needed", "Conditions apply", "Information only".
QString restrictionWords(Restriction restriction);
// Either standard's spelling (ED-318's "REQ_AUTHORIZATION" too); nullopt for anything else.
std::optional<Restriction> restrictionFromName(const QString &name);

enum class Format { Ed269, Ed318 };
QString formatName(Format format);  // "ED-269", "ED-318"

// A vertical limit in metres over the ground (AGL) or mean sea level (AMSL, EGM96). A WGS-84
// (ellipsoidal) limit in the file is converted to AMSL where its volume is, feet to metres.
enum class VerticalReference { Agl, Amsl };
struct VerticalLimit
{
    double metres = 0.0;
    VerticalReference reference = VerticalReference::Amsl;
    bool operator==(const VerticalLimit &) const = default;
};

// One polygon: rings[0] the outer boundary, the others holes; open (no repeated closing vertex).
struct Polygon
{
    std::vector<std::vector<GeoPoint>> rings;
    bool operator==(const Polygon &) const = default;
};

struct Circle
{
    GeoPoint center;
    double radius = 0.0;  // metres
    bool operator==(const Circle &) const = default;
};

// One airspace volume of a zone: polygons or a circle, between two limits.
struct Volume
{
    std::vector<Polygon> polygons;  // empty for a circle
    std::optional<Circle> circle;
    std::optional<VerticalLimit> lower;  // none: from the ground
    std::optional<VerticalLimit> upper;  // none: unlimited (the files' 99999)
    bool operator==(const Volume &) const = default;
};

// A daily period on some weekdays. Seconds from UTC midnight of the day it is given for (an offset
// in the file moves them, so they may be below 0 or above a day); an end at or before its start
// runs into the next day (22:00 to 02:00).
struct DailyPeriod
{
    std::uint8_t days = 0;  // bit 0 Monday ... bit 6 Sunday
    int start = 0;
    int end = 0;
    bool overnight = false;
    bool operator==(const DailyPeriod &) const = default;
};

// When a zone applies: always (permanent), or between two moments (either open), on a weekly
// schedule within them (none: all day).
struct TimePeriod
{
    bool permanent = false;
    std::optional<QDateTime> start, end;  // UTC
    std::vector<DailyPeriod> schedule;
    bool operator==(const TimePeriod &) const = default;
};

// A flight's window, UTC: from its planned start to its end by the time model.
struct TimeWindow
{
    QDateTime from, to;
};

// Whether the periods apply at some moment of [from, to] (no periods: always).
bool appliesDuring(const std::vector<TimePeriod> &periods, const TimeWindow &window);
// "always", "2026-06-01 00:00 to 2026-09-30 23:59, Sat Sun 18:00–23:00", in `zone`'s offset from
// UTC (the operator's time zone; local time without one).
QString applicabilityText(const std::vector<TimePeriod> &periods, const QTimeZone &zone);

// Who is responsible for a zone, and how to reach them (each text as the file gives it).
struct Authority
{
    QString name, service, contactName, siteUrl, email, phone;
    QString purpose;         // AUTHORIZATION, NOTIFICATION, INFORMATION
    QString intervalBefore;  // ISO 8601 duration: how long before the flight to ask ("P3D")
    bool operator==(const Authority &) const = default;
};
// "FOCA (UAS zone manager), drones@foca.ch, +41 58 465 80 39, https://foca.ch; ask P3D before".
QString contactText(const Authority &authority);

struct GeoZone
{
    Format format = Format::Ed269;
    QString identifier;  // the zone's identifier in its country
    QString country;     // ISO 3166-1 alpha-3
    QString name;        // the file's (first) name; the identifier when it has none
    Restriction restriction = Restriction::Prohibited;
    QStringList restrictionConditions;
    QStringList reasons;  // AIR_TRAFFIC, SENSITIVE, PRIVACY, POPULATION, NATURE, ...
    QString otherReasonInfo;
    QString message;
    QStringList uSpaceClasses;
    std::vector<TimePeriod> applicability;  // empty: always
    std::vector<Authority> authorities;
    std::vector<Volume> volumes;  // at least one
    bool operator==(const GeoZone &) const = default;

    bool appliesDuring(const TimeWindow &window) const { return ed::appliesDuring(applicability, window); }
};

// What one zone file gave: its zones, and each feature left out with the reason.
struct GeoZoneFile
{
    Format format = Format::Ed269;
    std::vector<GeoZone> zones;
    QStringList problems;
    std::optional<QDateTime> issued;  // ED-318's metadata, when the file says
};

} // namespace sortie::airspace::ed
