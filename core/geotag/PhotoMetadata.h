#pragma once

#include <QString>

#include <cstdint>
#include <optional>

namespace sortie::geotag {

// What a photo says about itself (EXIF, else XMP): when it was taken and with what. A value the
// photo does not hold is absent, never 0.
struct PhotoInfo
{
    QString path;
    QString fileName; // the name in its folder
    // DateTimeOriginal (+ SubSecTimeOriginal) read as UTC, corrected by OffsetTimeOriginal when the
    // photo has one: ms since the epoch. Absent when the photo holds no capture time.
    std::optional<int64_t> cameraTimeUtc;
    // The camera's OffsetTimeOriginal in seconds east of UTC; absent: the camera clock is taken as UTC.
    std::optional<int> cameraUtcOffsetSeconds;
    QString timeSource; // the tag the time came from ("Exif.Photo.DateTimeOriginal", "Xmp.exif.DateTimeOriginal")
    QString make, model;
    std::optional<double> focalLengthMm;
    std::optional<int> width, height; // pixels
};

// Where a photo was taken, as written into its copy. Absent heights are not written.
struct GeoTag
{
    double latitude = 0;  // degrees, WGS-84
    double longitude = 0; // degrees
    std::optional<double> altitudeAmsl;       // m above mean sea level
    std::optional<double> heightAboveTakeoff; // m above the take-off point
    int64_t time = 0;                         // UTC, ms since the epoch: GPSDateStamp and GPSTimeStamp
    // The camera's pitch, degrees from the horizon, -90 straight down (the photogrammetry tools'
    // convention: UgCS's tilt negated), when the vehicle reported its gimbal.
    std::optional<double> gimbalPitch;
};

// The XMP namespace of the height above take-off and the gimbal (docs/geotag.md):
// Xmp.sortie.RelativeAltitude, metres above the take-off point, and Xmp.sortie.GimbalPitch, degrees
// (-90 down), as decimal text.
inline constexpr char kSortieXmpNamespace[] = "http://ns.sortie.invalid/geotag/1.0/";
inline constexpr char kSortieXmpPrefix[] = "sortie";

// The one door to exiv2: no exiv2 type is seen outside PhotoMetadata.cpp. Each call opens the file,
// does its job and closes it; any exiv2 failure is a reason in *error (translated, without the
// file's name: the caller names the file), never an exception.
class PhotoMetadataFile
{
public:
    // Reads a photo's capture time, camera and size. nullopt with *error when exiv2 cannot read it.
    static std::optional<PhotoInfo> read(const QString &path, QString *error);
    // Replaces the photo's GPS tags with `tag` (EXIF GPSInfo, WGS-84, and the XMP height above
    // take-off) in place. Only ever called on a copy.
    static bool writeGeoTag(const QString &path, const GeoTag &tag, QString *error);
    // exiv2's version, for the log.
    static QString libraryVersion();
};

// Parses EXIF's "YYYY:MM:DD HH:MM:SS" with its sub-second digits ("123" is 0.123 s) and offset
// ("+02:00"): UTC ms since the epoch. nullopt for a blank, zero or malformed time; a malformed
// offset is *offsetError (the time is then not trusted either).
std::optional<int64_t> exifTimeToUtc(const QString &dateTime, const QString &subSec, const QString &offset,
                                     std::optional<int> *offsetSeconds = nullptr, bool *offsetError = nullptr);

} // namespace sortie::geotag
