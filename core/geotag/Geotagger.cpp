#include "Geotagger.h"

#include "EventPairing.h"
#include "GeotagLog.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QSaveFile>
#include <QTimeZone>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace sortie::geotag {

namespace {

QString utc(int64_t ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms, QTimeZone::utc()).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")) + QStringLiteral(" UTC");
}

QString seconds(int64_t ms)
{
    return QString::number(double(ms) / 1000.0, 'f', 1);
}

std::optional<double> present(double v)
{
    return std::isnan(v) ? std::nullopt : std::optional<double>(v);
}

std::optional<double> between(double a, double b, double f)
{
    if (std::isnan(a) || std::isnan(b))
        return std::nullopt;
    return a + f * (b - a);
}

QString number(double v, int decimals)
{
    return QString::number(v, 'f', decimals);
}

} // namespace

std::optional<TrackPosition> positionAt(const Track &track, int64_t time, int64_t maxGapMs, QString *reason)
{
    auto refuse = [&](const QString &why) -> std::optional<TrackPosition> {
        if (reason)
            *reason = why;
        return std::nullopt;
    };
    const auto &points = track.points;
    if (points.empty())
        return refuse(QCoreApplication::translate("Geotag", "the track holds no positions"));
    if (time < track.start())
        return refuse(QCoreApplication::translate("Geotag", "taken at %1, %2 s before the track starts (%3)")
                          .arg(utc(time), seconds(track.start() - time), utc(track.start())));
    if (time > track.end())
        return refuse(QCoreApplication::translate("Geotag", "taken at %1, %2 s after the track ends (%3)")
                          .arg(utc(time), seconds(time - track.end()), utc(track.end())));
    const auto after = std::lower_bound(points.begin(), points.end(), time, [](const TrackPoint &p, int64_t t) { return p.time < t; });
    TrackPosition position;
    if (after->time == time) {
        position.latitude = after->latitude;
        position.longitude = after->longitude;
        position.altitudeAmsl = present(after->altitudeAmsl);
        position.heightAboveTakeoff = present(after->heightAboveTakeoff);
        position.heading = present(after->heading);
        return position;
    }
    const TrackPoint &a = *(after - 1), &b = *after;
    if (b.time - a.time > maxGapMs)
        return refuse(QCoreApplication::translate("Geotag", "taken at %1, in a gap of %2 s in the track (from %3 to %4; at most %5 s is bridged)")
                          .arg(utc(time), seconds(b.time - a.time), utc(a.time), utc(b.time), seconds(maxGapMs)));
    const double f = double(time - a.time) / double(b.time - a.time);
    position.latitude = a.latitude + f * (b.latitude - a.latitude);
    double dLon = b.longitude - a.longitude;
    if (dLon > 180)
        dLon -= 360;
    else if (dLon < -180)
        dLon += 360;
    double lon = a.longitude + f * dLon;
    if (lon > 180)
        lon -= 360;
    else if (lon < -180)
        lon += 360;
    position.longitude = lon;
    position.altitudeAmsl = between(a.altitudeAmsl, b.altitudeAmsl, f);
    position.heightAboveTakeoff = between(a.heightAboveTakeoff, b.heightAboveTakeoff, f);
    if (!std::isnan(a.heading) && !std::isnan(b.heading)) {
        const double h = std::fmod(a.heading + f * std::remainder(b.heading - a.heading, 360.0), 360.0);
        position.heading = h < 0 ? h + 360 : h;
    }
    return position;
}

std::optional<double> courseAt(const Track &track, int64_t time, int64_t maxGapMs)
{
    if (track.points.empty())
        return std::nullopt;
    const auto from = positionAt(track, std::max(track.start(), time - 1000), maxGapMs, nullptr);
    const auto to = positionAt(track, std::min(track.end(), time + 1000), maxGapMs, nullptr);
    if (!from || !to)
        return std::nullopt;
    // Metres east and north on the sphere: enough for a bearing over two seconds of flight.
    constexpr double kMetresPerDegree = 111'195.0;
    const double north = (to->latitude - from->latitude) * kMetresPerDegree;
    const double east = std::remainder(to->longitude - from->longitude, 360.0) * kMetresPerDegree
                      * std::cos(0.5 * (from->latitude + to->latitude) * std::numbers::pi / 180.0);
    if (std::hypot(east, north) < 1.0)
        return std::nullopt;
    const double bearing = std::atan2(east, north) * 180.0 / std::numbers::pi;
    return bearing < 0 ? bearing + 360 : bearing;
}

QStringList photoFiles(const QString &folder)
{
    static const QStringList filters{QStringLiteral("*.jpg"), QStringLiteral("*.jpeg"), QStringLiteral("*.tif"),
                                     QStringLiteral("*.tiff"), QStringLiteral("*.dng")};
    QDir dir(folder);
    dir.setNameFilters(filters);
    dir.setFilter(QDir::Files | QDir::Hidden);
    dir.setSorting(QDir::Name);
    QStringList names;
    for (const QString &name : dir.entryList()) // QDir's name filters ignore case
        if (!name.startsWith(QLatin1Char('.')))
            names.append(name);
    return names;
}

QJsonObject GeotagReport::toJson() const
{
    QJsonArray list;
    for (const UntaggedPhoto &u : untagged)
        list.append(QJsonObject{{QStringLiteral("file"), u.file}, {QStringLiteral("reason"), u.reason}});
    QJsonArray missingList;
    for (int64_t sequence : missing)
        missingList.append(qint64(sequence));
    return QJsonObject{{QStringLiteral("photos"), photos},
                       {QStringLiteral("tagged"), int(tagged.size())},
                       {QStringLiteral("offset"), offsetSeconds},
                       {QStringLiteral("matchedBy"), byEvents ? QStringLiteral("events") : QStringLiteral("time")},
                       {QStringLiteral("missing"), missingList},
                       {QStringLiteral("untagged"), list}};
}

namespace {

// The photos paired with the track's photo events; nullopt when they do not pair.
std::optional<GeotagReport> matchByEvents(const std::vector<PhotoInfo> &photos, const Track &track, const MatchOptions &options)
{
    std::vector<size_t> timed; // photos with a time, in time order
    for (size_t i = 0; i < photos.size(); ++i)
        if (photos[i].cameraTimeUtc)
            timed.push_back(i);
    std::stable_sort(timed.begin(), timed.end(), [&](size_t a, size_t b) { return *photos[a].cameraTimeUtc < *photos[b].cameraTimeUtc; });
    std::vector<int64_t> cameraTimes, eventTimes;
    for (size_t i : timed)
        cameraTimes.push_back(*photos[i].cameraTimeUtc);
    for (const TrackPhoto &p : track.photos)
        eventTimes.push_back(p.time);
    const auto pairing = pairWithEvents(cameraTimes, eventTimes);
    if (!pairing)
        return std::nullopt;
    GeotagReport report;
    report.photos = int(photos.size());
    report.byEvents = true;
    report.offsetSeconds = double(pairing->offsetMs) / 1000.0;
    std::vector<int> eventOf(photos.size(), -1);
    for (const auto &[photo, event] : pairing->pairs)
        eventOf[timed[photo]] = int(event);
    for (size_t e : pairing->unpairedEvents)
        report.missing.push_back(track.photos[e].sequence);
    for (size_t i = 0; i < photos.size(); ++i) {
        const PhotoInfo &photo = photos[i];
        if (!photo.cameraTimeUtc) {
            report.untagged.push_back({photo.fileName, QCoreApplication::translate("Geotag", "it holds no capture time (EXIF DateTimeOriginal or XMP exif:DateTimeOriginal)")});
            continue;
        }
        if (eventOf[i] < 0) {
            report.untagged.push_back({photo.fileName, QCoreApplication::translate("Geotag", "no photo the vehicle reported taking matches its time (a shot before or after the flight, or another camera's)")});
            continue;
        }
        const TrackPhoto &event = track.photos[size_t(eventOf[i])];
        // Where the vehicle said; the height above take-off from the track at that moment.
        QString reason;
        TrackPosition position = positionAt(track, event.time, options.maxGapMs, &reason).value_or(TrackPosition{});
        position.latitude = event.latitude;
        position.longitude = event.longitude;
        if (std::isfinite(event.altitudeAmsl))
            position.altitudeAmsl = event.altitudeAmsl;
        if (std::isfinite(event.heading))
            position.heading = event.heading;
        if (std::isfinite(event.gimbalTilt))
            position.gimbalTilt = event.gimbalTilt;
        report.tagged.push_back({photo, event.time, position, {}});
    }
    return report;
}

} // namespace

GeotagReport matchPhotos(const std::vector<PhotoInfo> &photos, const Track &track, const MatchOptions &options)
{
    if (options.byEvents && !track.photos.empty())
        if (auto byEvents = matchByEvents(photos, track, options))
            return std::move(*byEvents);
    GeotagReport report;
    report.photos = int(photos.size());
    report.offsetSeconds = double(options.offsetMs) / 1000.0;
    for (const PhotoInfo &photo : photos) {
        if (!photo.cameraTimeUtc) {
            report.untagged.push_back({photo.fileName, QCoreApplication::translate("Geotag", "it holds no capture time (EXIF DateTimeOriginal or XMP exif:DateTimeOriginal)")});
            continue;
        }
        const int64_t time = *photo.cameraTimeUtc + options.offsetMs;
        QString reason;
        const auto position = positionAt(track, time, options.maxGapMs, &reason);
        if (!position) {
            report.untagged.push_back({photo.fileName, reason});
            continue;
        }
        report.tagged.push_back({photo, time, *position, {}});
    }
    return report;
}

bool writeGeotagged(GeotagReport &report, const QString &outFolder, QString *error)
{
    const QDir out(outFolder);
    std::vector<TaggedPhoto> written;
    written.reserve(report.tagged.size());
    for (TaggedPhoto &t : report.tagged) {
        const QString target = out.filePath(t.photo.fileName);
        const QString temporary = out.filePath(QStringLiteral(".%1.sortie-geotag").arg(t.photo.fileName));
        QString why;
        // std::filesystem's copy (the kernel's copy_file_range or sendfile), not QFile::copy, which
        // syncs every copy to disk: 8 ms a photo instead of 1 on a busy disk (docs/performance.md).
        std::error_code ec;
        bool ok = std::filesystem::copy_file(QFile::encodeName(t.photo.path).toStdString(), QFile::encodeName(temporary).toStdString(),
                                             std::filesystem::copy_options::overwrite_existing, ec);
        if (!ok) {
            why = QCoreApplication::translate("Geotag", "its copy cannot be made in %1: %2").arg(outFolder, QString::fromStdString(ec.message()));
        } else {
            GeoTag tag;
            tag.latitude = t.position.latitude;
            tag.longitude = t.position.longitude;
            tag.altitudeAmsl = t.position.altitudeAmsl;
            tag.heightAboveTakeoff = t.position.heightAboveTakeoff;
            if (t.position.gimbalTilt)
                tag.gimbalPitch = -*t.position.gimbalTilt; // tilt 90 (down) is pitch -90
            tag.time = t.time;
            ok = PhotoMetadataFile::writeGeoTag(temporary, tag, &why);
            if (ok) {
                std::filesystem::rename(QFile::encodeName(temporary).toStdString(), QFile::encodeName(target).toStdString(), ec);
                if (ec) {
                    ok = false;
                    why = QCoreApplication::translate("Geotag", "its copy cannot be put in place: %1").arg(QString::fromStdString(ec.message()));
                }
            }
        }
        if (!ok) {
            QFile::remove(temporary);
            qCWarning(lcGeotag).noquote() << t.photo.path << "not tagged:" << why;
            report.untagged.push_back({t.photo.fileName, why});
            continue;
        }
        t.copy = target;
        written.push_back(std::move(t));
    }
    report.tagged = std::move(written);
    std::sort(report.untagged.begin(), report.untagged.end(), [](const UntaggedPhoto &a, const UntaggedPhoto &b) { return a.file < b.file; });

    // OpenDroneMap's geo.txt: the CRS, then "name x y [z]" (x the longitude); Pix4D and Metashape
    // read "name,latitude,longitude,altitude" with a '#' comment first.
    QByteArray geo = "EPSG:4326\n", csv = "#name,latitude,longitude,altitude\n";
    for (const TaggedPhoto &t : report.tagged) {
        const QByteArray name = t.photo.fileName.toUtf8();
        const QByteArray lat = number(t.position.latitude, 8).toLatin1(), lon = number(t.position.longitude, 8).toLatin1();
        const QByteArray alt = t.position.altitudeAmsl ? number(*t.position.altitudeAmsl, 3).toLatin1() : QByteArray();
        geo += name + ' ' + lon + ' ' + lat + (alt.isEmpty() ? QByteArray() : ' ' + alt) + '\n';
        csv += name + ',' + lat + ',' + lon + ',' + alt + '\n';
    }
    for (const auto &[name, bytes, path] : {std::tuple{kGeoTxtName, geo, &report.geoTxt}, std::tuple{kCsvName, csv, &report.csv}}) {
        QSaveFile file(out.filePath(QString::fromLatin1(name)));
        if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
            if (error)
                *error = file.fileName() + QStringLiteral(": ") + file.errorString();
            return false;
        }
        *path = file.fileName();
    }
    return true;
}

std::optional<PhotoFolder> readPhotoFolder(const QString &photoFolder, QString *error)
{
    auto fail = [&](const QString &message) -> std::optional<PhotoFolder> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const QFileInfo folder(photoFolder);
    if (!folder.isDir() || !folder.isReadable())
        return fail(QCoreApplication::translate("Geotag", "%1 is not a folder of photos that can be read").arg(photoFolder));
    const QStringList names = photoFiles(photoFolder);
    if (names.isEmpty())
        return fail(QCoreApplication::translate("Geotag", "%1 holds no photos (.jpg, .jpeg, .tif, .tiff, .dng)").arg(photoFolder));
    PhotoFolder read;
    read.files = int(names.size());
    const QDir dir(photoFolder);
    for (const QString &name : names) {
        QString why;
        auto info = PhotoMetadataFile::read(dir.filePath(name), &why);
        if (!info) {
            qCInfo(lcGeotag).noquote() << dir.filePath(name) << "skipped:" << why; // the report names it
            read.unreadable.push_back({name, why});
            continue;
        }
        info->fileName = name;
        read.photos.push_back(std::move(*info));
    }
    return read;
}

std::optional<GeotagReport> geotagFolder(const QString &photoFolder, const Track &track, const GeotagOptions &options, QString *error)
{
    auto fail = [&](const QString &message) -> std::optional<GeotagReport> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const QFileInfo folder(photoFolder);
    auto folderRead = readPhotoFolder(photoFolder, error);
    if (!folderRead)
        return std::nullopt;
    if (options.outFolder.isEmpty())
        return fail(QCoreApplication::translate("Geotag", "no folder given for the geotagged copies"));
    if (!QDir().mkpath(options.outFolder))
        return fail(QCoreApplication::translate("Geotag", "%1: the folder for the geotagged copies cannot be made").arg(options.outFolder));
    if (QFileInfo(options.outFolder).canonicalFilePath() == folder.canonicalFilePath())
        return fail(QCoreApplication::translate("Geotag", "%1 is the photos' own folder: the copies go elsewhere, the originals are never changed").arg(options.outFolder));

    GeotagReport report = matchPhotos(folderRead->photos, track, options.match);
    report.photos = folderRead->files;
    report.untagged.insert(report.untagged.end(), folderRead->unreadable.begin(), folderRead->unreadable.end());
    if (!writeGeotagged(report, options.outFolder, error))
        return std::nullopt;
    qCInfo(lcGeotag).noquote() << photoFolder << ":" << report.tagged.size() << "of" << report.photos << "photos tagged into" << options.outFolder;
    return report;
}

} // namespace sortie::geotag
