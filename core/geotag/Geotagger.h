#pragma once

#include "PhotoMetadata.h"
#include "Track.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace sortie::geotag {

// Where the track puts a photo taken at a time: between the two track points around it, linear in
// latitude, longitude (across the antimeridian the short way) and heights. A height either
// point lacks is missing.
struct TrackPosition
{
    double latitude = 0, longitude = 0;
    std::optional<double> altitudeAmsl, heightAboveTakeoff;
    std::optional<double> heading; // degrees from north, where the nose points, when the track has it
    std::optional<double> gimbalTilt; // degrees, 90 down (UgCS's): from the vehicle's photo event
};

struct MatchOptions
{
    int64_t offsetMs = 0;      // added to the camera's clock (UTC) to give the track's time (by time)
    int64_t maxGapMs = 5000;   // a photo between track points further apart than this is not placed
    // With the track's photo events (a flight log's), pair the photos with them and find the offset
    // (EventPairing.h); false: by time along the track with `offsetMs`, as with no events.
    bool byEvents = true;
};

// The position at `time`, or why there is none (outside the track's span, in a gap), translated.
std::optional<TrackPosition> positionAt(const Track &track, int64_t time, int64_t maxGapMs, QString *reason);

// The direction of travel at `time`: the bearing from where the track is a second before to where it
// is a second after (within its span), in degrees from north. Absent when either is not on the
// track or the vehicle moved less than a metre (hovering has no course).
std::optional<double> courseAt(const Track &track, int64_t time, int64_t maxGapMs);

// The image files a photo folder holds, by name (.jpg, .jpeg, .tif, .tiff, .dng in any case; not
// its sub-folders).
QStringList photoFiles(const QString &folder);

struct TaggedPhoto
{
    PhotoInfo photo;
    int64_t time = 0; // the photo's time on the track's clock (camera UTC + offset), ms
    TrackPosition position;
    QString copy;     // the geotagged copy's path
};

struct UntaggedPhoto
{
    QString file;   // its name in the folder
    QString reason; // translated
};

struct GeotagReport
{
    int photos = 0;
    std::vector<TaggedPhoto> tagged;
    std::vector<UntaggedPhoto> untagged;
    double offsetSeconds = 0;      // the one given, or (by events) the one found
    bool byEvents = false;         // paired with the flight's photo events rather than placed by time
    std::vector<int64_t> missing;  // by events: the sequence numbers of photo events no photo matched
    QString geoTxt, csv; // the files written beside the copies
    // {"photos": N, "tagged": N, "offset": S, "matchedBy": "events"|"time", "missing": [SEQUENCE, …],
    //  "untagged": [{"file": NAME, "reason": "…"}]}
    QJsonObject toJson() const;
};

// What a photo folder holds, read: the photos exiv2 reads (each with its file name), and the ones
// it cannot with the reason.
struct PhotoFolder
{
    int files = 0;
    std::vector<PhotoInfo> photos;
    std::vector<UntaggedPhoto> unreadable;
};
// nullopt with *error when the folder cannot be read or holds no photo.
std::optional<PhotoFolder> readPhotoFolder(const QString &folder, QString *error);

struct GeotagOptions
{
    QString outFolder;
    MatchOptions match;
};

// Geotags the photos of a folder against a track: reads each one's time (an unreadable photo is
// named with the reason and skipped), places it on the track, writes a geotagged copy into the out
// folder (the original is only ever read), then OpenDroneMap's geo.txt and geotags.csv (Pix4D,
// Metashape) for the tagged ones. nullopt with *error only when nothing can be done: the photo
// folder cannot be read or holds no photo, the out folder is the photo folder or cannot be made.
std::optional<GeotagReport> geotagFolder(const QString &photoFolder, const Track &track, const GeotagOptions &options, QString *error);

// The same for photos already read (the benchmark times the steps apart). With the track's photo
// events (and `byEvents`), each photo paired with one is placed where the vehicle said it took it
// (its height above take-off from the track at that time), a photo no event matches is named
// unplaced, and the events without a photo are listed as missing; when the pattern does not match
// (too few pairs), by time as without events.
GeotagReport matchPhotos(const std::vector<PhotoInfo> &photos, const Track &track, const MatchOptions &options);
// Writes the copies of the matched photos and the two lists; a copy that cannot be written moves
// its photo to the untagged ones with the reason. false with *error when a list cannot be written.
bool writeGeotagged(GeotagReport &report, const QString &outFolder, QString *error);

inline constexpr char kGeoTxtName[] = "geo.txt";
inline constexpr char kCsvName[] = "geotags.csv";

} // namespace sortie::geotag
