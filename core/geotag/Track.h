#pragma once

#include <QString>

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace sortie::flightlog {
class FlightLog;
}

namespace sortie::geotag {

// One position of the vehicle (or the logger) at one time. A height the source does not give is
// NaN (missing), never 0.
struct TrackPoint
{
    int64_t time = 0;           // UTC, ms since the epoch
    double latitude = 0;        // degrees, WGS-84
    double longitude = 0;       // degrees
    double altitudeAmsl = std::numeric_limits<double>::quiet_NaN();       // m above mean sea level; NaN when unknown
    double heightAboveTakeoff = std::numeric_limits<double>::quiet_NaN(); // m above the take-off point; NaN when unknown
    double heading = std::numeric_limits<double>::quiet_NaN(); // degrees from north, where the nose points; NaN when unknown
};

// A photo the vehicle reported taking (a flight log's photo event): when on the vehicle's clock,
// where, and how it stood. A value it did not report is NaN.
struct TrackPhoto
{
    int64_t time = 0;       // UTC, ms since the epoch
    int64_t sequence = 0;   // as the vehicle counted
    double latitude = 0, longitude = 0;
    double altitudeAmsl = std::numeric_limits<double>::quiet_NaN();
    double heading = std::numeric_limits<double>::quiet_NaN();    // degrees, the vehicle's yaw
    double gimbalTilt = std::numeric_limits<double>::quiet_NaN(); // degrees: 90 looks down
};

// Positions in time order, one per time, from one source.
struct Track
{
    QString source; // the file, for messages
    std::vector<TrackPoint> points;
    std::vector<TrackPhoto> photos; // in time order; none from a GPX file or a log without photo events
    int64_t start() const { return points.empty() ? 0 : points.front().time; }
    int64_t end() const { return points.empty() ? 0 : points.back().time; }
    // Sorts by time and keeps the last point of each time.
    void normalise();
};

// A GPX 1.0 or 1.1 file's track points (every trk and trkseg, in time order): lat and lon, <ele>
// as metres AMSL, <time> UTC (a time without a zone is UTC, as GPX says). Waypoints and routes are
// not a track. nullopt with *error naming the file and its line for a file that is no GPX, a point
// with a bad or missing lat, lon or time, a bad <ele>; and for a GPX without track points.
std::optional<Track> readGpxTrack(const QString &path, QString *error);

// One vehicle of a Sortie flight log as a track: every position it reported (and every photo it
// reported taking, its photo events), its altitude AMSL,
// its heading (the short way round between samples)
// and its height above take-off (AltitudeAgl, the height above the home point's ground, else the
// altitude AMSL less the home's) interpolated to the position's time from samples at most
// `maxGapMs` apart. nullopt with *error when the vehicle reported no position.
std::optional<Track> flightLogTrack(const flightlog::FlightLog &log, int vehicle, QString *error, int64_t maxGapMs = 2000);

// Whether a file is a Sortie flight log (SQLite) rather than a GPX, by its first bytes.
bool looksLikeFlightLog(const QString &path);

} // namespace sortie::geotag
