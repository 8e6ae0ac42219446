// The one file of Sortie that speaks exiv2 (docs/geotag.md): photos' EXIF and XMP read, and the GPS
// tags of a copy written. exiv2 0.27 hands out std::auto_ptr, deprecated in C++20 but still in
// libstdc++: its warnings are silenced for this file alone (CMakeLists.txt).
#include "PhotoMetadata.h"

#include "GeotagLog.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTimeZone>

#include <exiv2/exiv2.hpp>

#include <cmath>
#include <mutex>

namespace sortie::geotag {

namespace {

// exiv2's warnings ("Directory Image: Next pointer is out of bounds") go to our log, not stderr.
void exivLog(int level, const char *message)
{
    const QString text = QString::fromUtf8(message).trimmed();
    if (level >= Exiv2::LogMsg::error)
        qCWarning(lcGeotag).noquote() << "exiv2:" << text;
    else
        qCInfo(lcGeotag).noquote() << "exiv2:" << text;
}

// The XMP toolkit is set up once, before any photo is read; our namespace registered with it.
void initialiseExiv2()
{
    static std::once_flag once;
    std::call_once(once, [] {
        Exiv2::LogMsg::setHandler(exivLog);
        Exiv2::LogMsg::setLevel(Exiv2::LogMsg::warn);
        Exiv2::XmpParser::initialize();
        Exiv2::XmpProperties::registerNs(kSortieXmpNamespace, kSortieXmpPrefix);
        qCDebug(lcGeotag) << "exiv2" << Exiv2::version();
    });
}

std::string localPath(const QString &path)
{
    return QFile::encodeName(path).toStdString();
}

QString exifText(const Exiv2::ExifData &exif, const char *key)
{
    const auto it = exif.findKey(Exiv2::ExifKey(key));
    if (it == exif.end() || it->count() == 0)
        return {};
    return QString::fromStdString(it->toString()).trimmed();
}

QString xmpText(const Exiv2::XmpData &xmp, const char *key)
{
    const auto it = xmp.findKey(Exiv2::XmpKey(key));
    if (it == xmp.end() || it->count() == 0)
        return {};
    return QString::fromStdString(it->toString()).trimmed();
}

std::optional<double> exifRational(const Exiv2::ExifData &exif, const char *key)
{
    const auto it = exif.findKey(Exiv2::ExifKey(key));
    if (it == exif.end() || it->count() == 0)
        return std::nullopt;
    const Exiv2::Rational r = it->toRational(0);
    if (r.second == 0)
        return std::nullopt; // 0/0: "unknown" in EXIF
    const double value = double(r.first) / double(r.second);
    return std::isfinite(value) && value > 0 ? std::optional<double>(value) : std::nullopt;
}

std::optional<int> exifPositive(const Exiv2::ExifData &exif, const char *key)
{
    const auto it = exif.findKey(Exiv2::ExifKey(key));
    if (it == exif.end() || it->count() == 0)
        return std::nullopt;
    const long v = it->toLong(0);
    return v > 0 && v < (1L << 30) ? std::optional<int>(int(v)) : std::nullopt;
}

// "+02:00", "-05:30", "Z": seconds east of UTC.
std::optional<int> parseOffset(const QString &text)
{
    if (text == QLatin1String("Z"))
        return 0;
    static const QRegularExpression re(QStringLiteral("^([+-])(\\d{2}):?(\\d{2})$"));
    const auto m = re.match(text);
    if (!m.hasMatch())
        return std::nullopt;
    const int hours = m.captured(2).toInt(), minutes = m.captured(3).toInt();
    if (hours > 14 || minutes > 59)
        return std::nullopt;
    const int seconds = hours * 3600 + minutes * 60;
    return m.captured(1) == QLatin1String("-") ? -seconds : seconds;
}

// XMP's ISO 8601 time ("2026-05-01T10:00:00.25+02:00", a date alone is no capture time).
std::optional<int64_t> xmpTimeToUtc(const QString &text, std::optional<int> *offsetSeconds)
{
    static const QRegularExpression re(QStringLiteral(
        "^(\\d{4})-(\\d{2})-(\\d{2})T(\\d{2}):(\\d{2})(?::(\\d{2})(?:[.,](\\d+))?)?(Z|[+-]\\d{2}:?\\d{2})?$"));
    const auto m = re.match(text);
    if (!m.hasMatch())
        return std::nullopt;
    const QString offset = m.captured(8);
    std::optional<int> zone;
    if (!offset.isEmpty()) {
        zone = parseOffset(offset);
        if (!zone)
            return std::nullopt;
    }
    const QString exif = QStringLiteral("%1:%2:%3 %4:%5:%6").arg(m.captured(1), m.captured(2), m.captured(3), m.captured(4), m.captured(5),
                                                                 m.captured(6).isEmpty() ? QStringLiteral("00") : m.captured(6));
    return exifTimeToUtc(exif, m.captured(7), offset.isEmpty() ? QString() : offset, offsetSeconds);
}

QString exivReason(const Exiv2::AnyError &e)
{
    return QCoreApplication::translate("Geotag", "exiv2 cannot read it (%1)").arg(QString::fromUtf8(e.what()).trimmed());
}

// Degrees as EXIF's three rationals, degrees/1 minutes/1 seconds/1000000, from one integer count
// of micro-arcseconds so that rounding never gives 60 seconds.
std::string dms(double degrees)
{
    const int64_t micro = int64_t(std::llround(std::fabs(degrees) * 3600e6));
    const int64_t d = micro / 3'600'000'000LL, m = (micro % 3'600'000'000LL) / 60'000'000LL, s = micro % 60'000'000LL;
    return std::to_string(d) + "/1 " + std::to_string(m) + "/1 " + std::to_string(s) + "/1000000";
}

} // namespace

std::optional<int64_t> exifTimeToUtc(const QString &dateTime, const QString &subSec, const QString &offset,
                                     std::optional<int> *offsetSeconds, bool *offsetError)
{
    if (offsetError)
        *offsetError = false;
    static const QRegularExpression re(QStringLiteral("^(\\d{4}):(\\d{2}):(\\d{2})[ T](\\d{2}):(\\d{2}):(\\d{2})$"));
    const auto m = re.match(dateTime.trimmed());
    if (!m.hasMatch())
        return std::nullopt;
    const QDate date(m.captured(1).toInt(), m.captured(2).toInt(), m.captured(3).toInt());
    const QTime time(m.captured(4).toInt(), m.captured(5).toInt(), m.captured(6).toInt());
    if (!date.isValid() || !time.isValid() || date.year() < 1900)
        return std::nullopt; // "0000:00:00 00:00:00" is a camera that never had its clock set
    int64_t ms = QDateTime(date, time, QTimeZone::utc()).toMSecsSinceEpoch();
    // Sub-second digits are a decimal fraction: "5" is 0.5 s, "050" 0.05 s, "123456" 0.123456 s (to the ms).
    static const QRegularExpression digits(QStringLiteral("^\\d+"));
    const QString frac = digits.match(subSec.trimmed()).captured(0);
    if (!frac.isEmpty())
        ms += std::llround((frac.left(9) + QStringLiteral("000000000")).left(9).toLongLong() / 1e6);
    const QString zone = offset.trimmed();
    if (!zone.isEmpty()) {
        const auto seconds = parseOffset(zone);
        if (!seconds) {
            if (offsetError)
                *offsetError = true;
            return std::nullopt;
        }
        ms -= int64_t(*seconds) * 1000;
        if (offsetSeconds)
            *offsetSeconds = seconds;
    } else if (offsetSeconds) {
        offsetSeconds->reset();
    }
    return ms;
}

std::optional<PhotoInfo> PhotoMetadataFile::read(const QString &path, QString *error)
{
    initialiseExiv2();
    try {
        Exiv2::Image::AutoPtr image = Exiv2::ImageFactory::open(localPath(path));
        if (!image.get()) {
            if (error)
                *error = QCoreApplication::translate("Geotag", "exiv2 cannot open it");
            return std::nullopt;
        }
        image->readMetadata();
        const Exiv2::ExifData &exif = image->exifData();
        const Exiv2::XmpData &xmp = image->xmpData();
        PhotoInfo info;
        info.path = path;
        info.fileName = QFileInfo(path).fileName();
        info.make = exifText(exif, "Exif.Image.Make");
        if (info.make.isEmpty())
            info.make = xmpText(xmp, "Xmp.tiff.Make");
        info.model = exifText(exif, "Exif.Image.Model");
        if (info.model.isEmpty())
            info.model = xmpText(xmp, "Xmp.tiff.Model");
        info.focalLengthMm = exifRational(exif, "Exif.Photo.FocalLength");
        if (image->pixelWidth() > 0 && image->pixelHeight() > 0) {
            info.width = image->pixelWidth();
            info.height = image->pixelHeight();
        } else {
            info.width = exifPositive(exif, "Exif.Photo.PixelXDimension");
            info.height = exifPositive(exif, "Exif.Photo.PixelYDimension");
        }

        const QString original = exifText(exif, "Exif.Photo.DateTimeOriginal");
        const QString offset = exifText(exif, "Exif.Photo.OffsetTimeOriginal");
        if (!original.isEmpty()) {
            bool badOffset = false;
            info.cameraTimeUtc = exifTimeToUtc(original, exifText(exif, "Exif.Photo.SubSecTimeOriginal"), offset,
                                               &info.cameraUtcOffsetSeconds, &badOffset);
            if (badOffset) {
                if (error)
                    *error = QCoreApplication::translate("Geotag", "its OffsetTimeOriginal \"%1\" is no time zone offset (±HH:MM)").arg(offset);
                return std::nullopt;
            }
            if (info.cameraTimeUtc)
                info.timeSource = QStringLiteral("Exif.Photo.DateTimeOriginal");
            else
                qCInfo(lcGeotag).noquote() << path << ": DateTimeOriginal" << original << "is no time";
        }
        if (!info.cameraTimeUtc) {
            const QString x = xmpText(xmp, "Xmp.exif.DateTimeOriginal");
            if (!x.isEmpty()) {
                info.cameraTimeUtc = xmpTimeToUtc(x, &info.cameraUtcOffsetSeconds);
                if (info.cameraTimeUtc)
                    info.timeSource = QStringLiteral("Xmp.exif.DateTimeOriginal");
            }
        }
        return info;
    } catch (const Exiv2::AnyError &e) {
        if (error)
            *error = exivReason(e);
    } catch (const std::exception &e) {
        if (error)
            *error = QCoreApplication::translate("Geotag", "exiv2 cannot read it (%1)").arg(QString::fromUtf8(e.what()));
    }
    return std::nullopt;
}

bool PhotoMetadataFile::writeGeoTag(const QString &path, const GeoTag &tag, QString *error)
{
    initialiseExiv2();
    if (!std::isfinite(tag.latitude) || !std::isfinite(tag.longitude) || std::fabs(tag.latitude) > 90 || std::fabs(tag.longitude) > 180) {
        if (error)
            *error = QCoreApplication::translate("Geotag", "no valid position to write");
        return false;
    }
    try {
        Exiv2::Image::AutoPtr image = Exiv2::ImageFactory::open(localPath(path));
        if (!image.get()) {
            if (error)
                *error = QCoreApplication::translate("Geotag", "exiv2 cannot open it");
            return false;
        }
        image->readMetadata();
        Exiv2::ExifData &exif = image->exifData();
        // The camera's own position, if it wrote one, gives way to the track's.
        for (auto it = exif.begin(); it != exif.end();) {
            if (it->groupName() == "GPSInfo")
                it = exif.erase(it);
            else
                ++it;
        }
        exif["Exif.GPSInfo.GPSVersionID"] = std::string("2 3 0 0");
        exif["Exif.GPSInfo.GPSLatitudeRef"] = std::string(tag.latitude < 0 ? "S" : "N");
        exif["Exif.GPSInfo.GPSLatitude"] = dms(tag.latitude);
        exif["Exif.GPSInfo.GPSLongitudeRef"] = std::string(tag.longitude < 0 ? "W" : "E");
        exif["Exif.GPSInfo.GPSLongitude"] = dms(tag.longitude);
        if (tag.altitudeAmsl && std::isfinite(*tag.altitudeAmsl)) {
            exif["Exif.GPSInfo.GPSAltitudeRef"] = std::string(*tag.altitudeAmsl < 0 ? "1" : "0");
            exif["Exif.GPSInfo.GPSAltitude"] = std::to_string(std::llround(std::fabs(*tag.altitudeAmsl) * 1000)) + "/1000";
        }
        exif["Exif.GPSInfo.GPSMapDatum"] = std::string("WGS-84");
        const QDateTime utc = QDateTime::fromMSecsSinceEpoch(tag.time, QTimeZone::utc());
        const QTime t = utc.time();
        exif["Exif.GPSInfo.GPSTimeStamp"] = std::to_string(t.hour()) + "/1 " + std::to_string(t.minute()) + "/1 " +
                                            std::to_string(t.second() * 1000 + t.msec()) + "/1000";
        exif["Exif.GPSInfo.GPSDateStamp"] = utc.date().toString(QStringLiteral("yyyy:MM:dd")).toStdString();

        Exiv2::XmpData &xmp = image->xmpData();
        const std::string relative = std::string("Xmp.") + kSortieXmpPrefix + ".RelativeAltitude";
        const auto old = xmp.findKey(Exiv2::XmpKey(relative));
        if (old != xmp.end())
            xmp.erase(old);
        if (tag.heightAboveTakeoff && std::isfinite(*tag.heightAboveTakeoff))
            xmp[relative] = QString::number(*tag.heightAboveTakeoff, 'f', 3).toStdString();
        const std::string pitch = std::string("Xmp.") + kSortieXmpPrefix + ".GimbalPitch";
        if (const auto oldPitch = xmp.findKey(Exiv2::XmpKey(pitch)); oldPitch != xmp.end())
            xmp.erase(oldPitch);
        if (tag.gimbalPitch && std::isfinite(*tag.gimbalPitch))
            xmp[pitch] = QString::number(*tag.gimbalPitch, 'f', 2).toStdString();
        image->writeMetadata();
    } catch (const Exiv2::AnyError &e) {
        if (error)
            *error = QCoreApplication::translate("Geotag", "exiv2 cannot write its tags (%1)").arg(QString::fromUtf8(e.what()).trimmed());
        return false;
    } catch (const std::exception &e) {
        if (error)
            *error = QCoreApplication::translate("Geotag", "exiv2 cannot write its tags (%1)").arg(QString::fromUtf8(e.what()));
        return false;
    }
    // exiv2 can write a file it then refuses (a JPEG with two damaged EXIF segments came back as "no
    // TIFF image", found by fuzz_photo_metadata): a copy is only called tagged once it reads back
    // with the position in it.
    try {
        Exiv2::Image::AutoPtr copy = Exiv2::ImageFactory::open(localPath(path));
        if (!copy.get())
            throw Exiv2::Error(Exiv2::kerFileContainsUnknownImageType);
        copy->readMetadata();
        const Exiv2::ExifData &written = copy->exifData();
        if (written.findKey(Exiv2::ExifKey("Exif.GPSInfo.GPSLatitude")) != written.end() &&
            written.findKey(Exiv2::ExifKey("Exif.GPSInfo.GPSLongitude")) != written.end())
            return true;
        if (error)
            *error = QCoreApplication::translate("Geotag", "exiv2 wrote its tags but they do not read back");
    } catch (const Exiv2::AnyError &e) {
        if (error)
            *error = QCoreApplication::translate("Geotag", "exiv2 wrote a copy it cannot read back (%1)").arg(QString::fromUtf8(e.what()).trimmed());
    } catch (const std::exception &e) {
        if (error)
            *error = QCoreApplication::translate("Geotag", "exiv2 wrote a copy it cannot read back (%1)").arg(QString::fromUtf8(e.what()));
    }
    return false;
}

QString PhotoMetadataFile::libraryVersion()
{
    return QString::fromLatin1(Exiv2::version());
}

} // namespace sortie::geotag
