#pragma once
// What the geotag tests share: small JPEGs they write themselves (QImage), their camera tags set
// and the copies' GPS tags read back with exiv2 directly (not through core/geotag, whose writing
// they check), GPX files and flight logs made on the spot. No file comes from outside.
#include "FlightLogWriter.h"
#include "RecordingChunk.h"

#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QPainter>
#include <QTimeZone>

#include <exiv2/exiv2.hpp>

#include <cmath>
#include <optional>
#include <stdexcept>

namespace sortie::test {

// 2026-05-01 10:00:00 UTC: where the test tracks start.
inline const int64_t kTrackStart = QDateTime(QDate(2026, 5, 1), QTime(10, 0), QTimeZone::utc()).toMSecsSinceEpoch();

// A small JPEG of its own: `seed` changes its pixels, so no two photos are the same bytes.
inline void writeJpeg(const QString &path, int seed, int width = 64, int height = 48)
{
    QImage image(width, height, QImage::Format_RGB32);
    image.fill(QColor::fromHsv((seed * 37) % 360, 200, 200));
    QPainter painter(&image);
    painter.drawLine(0, seed % height, width, (seed * 7) % height);
    painter.end();
    if (!image.save(path, "JPEG", 90))
        throw std::runtime_error("cannot write " + path.toStdString());
}

struct CameraTags
{
    QString dateTimeOriginal;  // "2026:05:01 10:00:05"; empty: none
    QString subSec;            // "250"; empty: none
    QString offset;            // "+02:00"; empty: none
    QString make = QStringLiteral("Sortie Test");
    QString model = QStringLiteral("Q-64");
    QString focalLength = QStringLiteral("88/10"); // rational; empty: none
};

inline void setCameraTags(const QString &path, const CameraTags &tags)
{
    auto image = Exiv2::ImageFactory::open(QFile::encodeName(path).toStdString());
    image->readMetadata();
    Exiv2::ExifData &exif = image->exifData();
    if (!tags.dateTimeOriginal.isEmpty())
        exif["Exif.Photo.DateTimeOriginal"] = tags.dateTimeOriginal.toStdString();
    if (!tags.subSec.isEmpty())
        exif["Exif.Photo.SubSecTimeOriginal"] = tags.subSec.toStdString();
    if (!tags.offset.isEmpty())
        exif["Exif.Photo.OffsetTimeOriginal"] = tags.offset.toStdString();
    if (!tags.make.isEmpty())
        exif["Exif.Image.Make"] = tags.make.toStdString();
    if (!tags.model.isEmpty())
        exif["Exif.Image.Model"] = tags.model.toStdString();
    if (!tags.focalLength.isEmpty())
        exif["Exif.Photo.FocalLength"] = tags.focalLength.toStdString();
    image->writeMetadata();
}

// A photo taken `ms` after the track's start, its camera clock on UTC.
inline CameraTags takenAt(int64_t msAfterStart)
{
    const QDateTime t = QDateTime::fromMSecsSinceEpoch(kTrackStart + msAfterStart, QTimeZone::utc());
    CameraTags tags;
    tags.dateTimeOriginal = t.toString(QStringLiteral("yyyy:MM:dd HH:mm:ss"));
    tags.subSec = QStringLiteral("%1").arg(t.time().msec(), 3, 10, QLatin1Char('0'));
    return tags;
}

inline QByteArray sha256(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256);
}

// The GPS tags of a geotagged copy, read back with exiv2.
struct ReadBack
{
    std::optional<double> latitude, longitude, altitude, relativeAltitude, gimbalPitch;
    QString latitudeRef, longitudeRef, datum, version, dateStamp, timeStamp;
    int altitudeRef = -1;
};

inline double fromDms(const Exiv2::Exifdatum &d)
{
    double value = 0;
    for (long i = 0; i < 3; ++i) {
        const Exiv2::Rational r = d.toRational(i);
        value += double(r.first) / double(r.second) / std::pow(60.0, double(i));
    }
    return value;
}

inline ReadBack readGps(const QString &path)
{
    Exiv2::XmpProperties::registerNs("http://ns.sortie.invalid/geotag/1.0/", "sortie");
    auto image = Exiv2::ImageFactory::open(QFile::encodeName(path).toStdString());
    image->readMetadata();
    const Exiv2::ExifData &exif = image->exifData();
    ReadBack r;
    auto find = [&](const char *key) { return exif.findKey(Exiv2::ExifKey(key)); };
    auto text = [&](const char *key) {
        const auto it = find(key);
        return it == exif.end() ? QString() : QString::fromStdString(it->toString()).trimmed();
    };
    r.latitudeRef = text("Exif.GPSInfo.GPSLatitudeRef");
    r.longitudeRef = text("Exif.GPSInfo.GPSLongitudeRef");
    r.datum = text("Exif.GPSInfo.GPSMapDatum");
    r.version = text("Exif.GPSInfo.GPSVersionID");
    r.dateStamp = text("Exif.GPSInfo.GPSDateStamp");
    if (auto it = find("Exif.GPSInfo.GPSLatitude"); it != exif.end())
        r.latitude = fromDms(*it) * (r.latitudeRef == QLatin1String("S") ? -1 : 1);
    if (auto it = find("Exif.GPSInfo.GPSLongitude"); it != exif.end())
        r.longitude = fromDms(*it) * (r.longitudeRef == QLatin1String("W") ? -1 : 1);
    if (auto it = find("Exif.GPSInfo.GPSAltitudeRef"); it != exif.end())
        r.altitudeRef = int(it->toLong(0));
    if (auto it = find("Exif.GPSInfo.GPSAltitude"); it != exif.end()) {
        const Exiv2::Rational q = it->toRational(0);
        r.altitude = double(q.first) / double(q.second) * (r.altitudeRef == 1 ? -1 : 1);
    }
    if (auto it = find("Exif.GPSInfo.GPSTimeStamp"); it != exif.end()) {
        const double s = double(it->toRational(2).first) / double(it->toRational(2).second);
        r.timeStamp = QStringLiteral("%1:%2:%3").arg(it->toRational(0).first, 2, 10, QLatin1Char('0'))
                          .arg(it->toRational(1).first, 2, 10, QLatin1Char('0')).arg(s, 6, 'f', 3, QLatin1Char('0'));
    }
    const Exiv2::XmpData &xmp = image->xmpData();
    if (auto it = xmp.findKey(Exiv2::XmpKey("Xmp.sortie.RelativeAltitude")); it != xmp.end()) {
        bool ok = false; // a value that is no number stays missing, and the comparison fails
        const double value = QString::fromStdString(it->toString()).toDouble(&ok);
        if (ok)
            r.relativeAltitude = value;
    }
    if (auto it = xmp.findKey(Exiv2::XmpKey("Xmp.sortie.GimbalPitch")); it != xmp.end()) {
        bool ok = false;
        const double value = QString::fromStdString(it->toString()).toDouble(&ok);
        if (ok)
            r.gimbalPitch = value;
    }
    return r;
}

// A GPX 1.1 track of `points` (time ms after kTrackStart, lat, lon, ele).
struct GpxPoint
{
    int64_t ms;
    double lat, lon, ele;
};

inline void writeGpx(const QString &path, const std::vector<GpxPoint> &points)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        throw std::runtime_error("cannot write " + path.toStdString());
    QByteArray xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                     "<gpx version=\"1.1\" creator=\"tst_geotag\" xmlns=\"http://www.topografix.com/GPX/1/1\">\n"
                     "  <trk><name>test</name><trkseg>\n";
    for (const GpxPoint &p : points) {
        const QString time = QDateTime::fromMSecsSinceEpoch(kTrackStart + p.ms, QTimeZone::utc()).toString(Qt::ISODateWithMs);
        xml += QStringLiteral("    <trkpt lat=\"%1\" lon=\"%2\"><ele>%3</ele><time>%4</time></trkpt>\n")
                   .arg(p.lat, 0, 'f', 9).arg(p.lon, 0, 'f', 9).arg(p.ele, 0, 'f', 3).arg(time).toUtf8();
    }
    xml += "  </trkseg></trk>\n</gpx>\n";
    f.write(xml);
}

// A flight log of vehicles flying `points` (ms after kTrackStart, lat, lon, AMSL, AGL), written by
// the real writer as a recording writes it: one chunk a second.
struct LoggedVehicle
{
    QString key, name;
    std::vector<std::array<double, 5>> samples; // ms, lat, lon, amsl, agl (NaN: not sent)
    std::vector<std::pair<double, double>> headings = {}; // ms, degrees (Heading), when the test sends them
};

inline QString writeFlightLog(const QString &path, const std::vector<LoggedVehicle> &vehicles)
{
    using F = vehicle::TelemetryField;
    flightlog::FlightLogWriter writer(path, {0, 0});
    QString error;
    if (!writer.open(&error))
        return error;
    int64_t last = 0;
    for (const auto &v : vehicles)
        for (const auto &s : v.samples)
            last = std::max(last, int64_t(s[0]));
    bool first = true;
    for (int64_t from = 0; from <= last; from += 1000) {
        flightlog::RecordingChunk chunk;
        if (first) {
            for (const auto &v : vehicles) {
                flightlog::RecordedVehicle rv{v.key, {}};
                rv.identity.id = v.key.section(QLatin1Char(':'), 1);
                rv.identity.name = v.name;
                rv.identity.protocol = QStringLiteral("VCI");
                chunk.vehicles.push_back(rv);
            }
            first = false;
        }
        for (const auto &v : vehicles) {
            flightlog::RecordedSamples rs;
            rs.vehicleKey = v.key;
            flightlog::FieldSamples lat{F::Latitude, {}}, lon{F::Longitude, {}}, amsl{F::AltitudeAmsl, {}}, agl{F::AltitudeAgl, {}}, heading{F::Heading, {}};
            for (const auto &[ms, degrees] : v.headings)
                if (ms >= double(from) && ms < double(from + 1000))
                    heading.samples.push_back({kTrackStart + int64_t(ms), degrees});
            for (const auto &s : v.samples) {
                if (s[0] < double(from) || s[0] >= double(from + 1000))
                    continue;
                const int64_t t = kTrackStart + int64_t(s[0]);
                lat.samples.push_back({t, s[1]});
                lon.samples.push_back({t, s[2]});
                if (!std::isnan(s[3]))
                    amsl.samples.push_back({t, s[3]});
                if (!std::isnan(s[4]))
                    agl.samples.push_back({t, s[4]});
            }
            for (auto *f : {&lat, &lon, &amsl, &agl, &heading})
                if (!f->samples.empty())
                    rs.fields.push_back(std::move(*f));
            if (!rs.fields.empty())
                chunk.samples.push_back(std::move(rs));
        }
        if (!chunk.empty())
            writer.write(chunk);
    }
    writer.close();
    return {};
}

} // namespace sortie::test
