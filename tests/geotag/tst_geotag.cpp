// core/geotag on photos the test makes: small JPEGs (QImage) whose camera tags are set with exiv2,
// GPX tracks and a real .sortielog (FlightLogWriter). The copies' GPS tags are read back with exiv2
// itself and compared with the position the test interpolates on its own; the originals stay byte
// for byte as they were; photos outside the track, in its gaps, without a time and files that are
// no photo are named with their reason.
#include "EventPairing.h"
#include "FlightLog.h"
#include "GeotagTestSupport.h"
#include "Geotagger.h"
#include "PhotoMetadata.h"
#include "TestData.h"
#include "Track.h"

#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

#include <numbers>

#include <cmath>

using namespace sortie;
using namespace sortie::geotag;
using test::kTrackStart;

namespace {

// A track that is no straight line: every second a step that grows, north-east, climbing; a gap of
// 20 s between 30 s and 50 s.
std::vector<test::GpxPoint> curvedTrack()
{
    std::vector<test::GpxPoint> points;
    double lat = 56.95, lon = 24.10, ele = 40;
    for (int s = 0; s <= 60; ++s) {
        if (s > 30 && s < 50)
            continue;
        points.push_back({int64_t(s) * 1000, lat, lon, ele});
        lat += 1e-5 * (1 + s % 7);
        lon += 2e-5 * (1 + (s * 3) % 5);
        ele += 0.25 * (s % 4);
    }
    return points;
}

// The test's own interpolation between the two points around t.
test::GpxPoint expectedAt(const std::vector<test::GpxPoint> &points, int64_t ms)
{
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        if (points[i].ms <= ms && ms <= points[i + 1].ms) {
            const double f = double(ms - points[i].ms) / double(points[i + 1].ms - points[i].ms);
            const auto &a = points[i], &b = points[i + 1];
            return {ms, a.lat + f * (b.lat - a.lat), a.lon + f * (b.lon - a.lon), a.ele + f * (b.ele - a.ele)};
        }
    }
    qFatal("no track point around %lld", static_cast<long long>(ms));
}

QString utcText(int64_t ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms, QTimeZone::utc()).toString(QStringLiteral("yyyy:MM:dd"));
}

} // namespace

class TestGeotag : public QObject
{
    Q_OBJECT

private slots:
    void exifTimes()
    {
        std::optional<int> zone;
        const int64_t base = QDateTime(QDate(2026, 5, 1), QTime(10, 0, 5), QTimeZone::utc()).toMSecsSinceEpoch();
        QCOMPARE(exifTimeToUtc(QStringLiteral("2026:05:01 10:00:05"), {}, {}, &zone), std::optional<int64_t>(base));
        QVERIFY(!zone); // no offset: the camera's clock is taken as UTC
        QCOMPARE(exifTimeToUtc(QStringLiteral("2026:05:01 10:00:05"), QStringLiteral("25"), {}), std::optional<int64_t>(base + 250));
        QCOMPARE(exifTimeToUtc(QStringLiteral("2026:05:01 10:00:05"), QStringLiteral("5"), {}), std::optional<int64_t>(base + 500));
        QCOMPARE(exifTimeToUtc(QStringLiteral("2026:05:01 10:00:05"), QStringLiteral("050"), {}), std::optional<int64_t>(base + 50));
        QCOMPARE(exifTimeToUtc(QStringLiteral("2026:05:01 12:00:05"), {}, QStringLiteral("+02:00"), &zone), std::optional<int64_t>(base));
        QCOMPARE(zone, std::optional<int>(7200));
        QCOMPARE(exifTimeToUtc(QStringLiteral("2026:05:01 04:30:05"), {}, QStringLiteral("-05:30")), std::optional<int64_t>(base));
        // Blank, zero and malformed times are no time; a bad offset is said to be one.
        for (const char *bad : {"", "    :  :     :  :  ", "0000:00:00 00:00:00", "2026-05-01 10:00:05", "2026:13:01 10:00:05"})
            QVERIFY2(!exifTimeToUtc(QString::fromLatin1(bad), {}, {}), bad);
        bool badOffset = false;
        QVERIFY(!exifTimeToUtc(QStringLiteral("2026:05:01 10:00:05"), {}, QStringLiteral("CEST"), nullptr, &badOffset));
        QVERIFY(badOffset);
    }

    void readsWhatThePhotoHolds()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.jpg"));
        test::writeJpeg(path, 1, 80, 60);
        auto tags = test::takenAt(5250);
        tags.offset = QStringLiteral("+00:00");
        test::setCameraTags(path, tags);
        QString error;
        const auto info = PhotoMetadataFile::read(path, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->cameraTimeUtc, std::optional<int64_t>(kTrackStart + 5250));
        QCOMPARE(info->cameraUtcOffsetSeconds, std::optional<int>(0));
        QCOMPARE(info->make, QStringLiteral("Sortie Test"));
        QCOMPARE(info->model, QStringLiteral("Q-64"));
        QVERIFY(info->focalLengthMm && std::fabs(*info->focalLengthMm - 8.8) < 1e-9);
        QCOMPARE(info->width, std::optional<int>(80));
        QCOMPARE(info->height, std::optional<int>(60));

        // What a photo does not hold is absent, not 0.
        const QString bare = dir.filePath(QStringLiteral("bare.jpg"));
        test::writeJpeg(bare, 2);
        const auto none = PhotoMetadataFile::read(bare, &error);
        QVERIFY2(none, qPrintable(error));
        QVERIFY(!none->cameraTimeUtc);
        QVERIFY(!none->focalLengthMm);
        QVERIFY(none->make.isEmpty());

        // A file that is no image is a reason, not a crash.
        const QString text = dir.filePath(QStringLiteral("notes.jpg"));
        QFile f(text);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("these are no photo's bytes\n");
        f.close();
        QVERIFY(!PhotoMetadataFile::read(text, &error));
        QVERIFY2(error.contains(QStringLiteral("exiv2")), qPrintable(error));
    }

    void gpxTrackTagsCopiesAndLeavesOriginals()
    {
        QTemporaryDir dir;
        const QString photos = dir.filePath(QStringLiteral("card")), out = dir.filePath(QStringLiteral("tagged"));
        QVERIFY(QDir().mkpath(photos));
        const auto points = curvedTrack();
        const QString gpx = dir.filePath(QStringLiteral("track.gpx"));
        test::writeGpx(gpx, points);

        // The operator says the camera's clock is 1.5 s behind: photo time = camera + 1.5 s.
        const int64_t offset = 1500;
        struct Shot { const char *name; int64_t trackMs; };
        const std::vector<Shot> good{{"IMG_0001.JPG", 0}, {"IMG_0002.JPG", 2250}, {"IMG_0003.jpg", 10'500},
                                     {"IMG_0004.jpeg", 29'999}, {"IMG_0005.JPG", 55'125}, {"IMG_0006.JPG", 60'000}};
        std::map<QString, QByteArray> before;
        int seed = 0;
        for (const Shot &s : good) {
            const QString path = QDir(photos).filePath(QString::fromLatin1(s.name));
            test::writeJpeg(path, ++seed);
            test::setCameraTags(path, test::takenAt(s.trackMs - offset));
        }
        // One in its camera's local time, two hours east of UTC.
        {
            const QString path = QDir(photos).filePath(QStringLiteral("IMG_0007.JPG"));
            test::writeJpeg(path, ++seed);
            auto tags = test::takenAt(20'000 - offset + 2 * 3600 * 1000);
            tags.offset = QStringLiteral("+02:00");
            test::setCameraTags(path, tags);
        }
        // Untagged: before the track, after it, in its gap, no time at all, no photo, empty.
        const std::map<QString, int64_t> outside{{QStringLiteral("IMG_0100.JPG"), -4000}, {QStringLiteral("IMG_0101.JPG"), 61'000},
                                                 {QStringLiteral("IMG_0102.JPG"), 40'000}};
        for (const auto &[name, ms] : outside) {
            const QString path = QDir(photos).filePath(name);
            test::writeJpeg(path, ++seed);
            test::setCameraTags(path, test::takenAt(ms - offset));
        }
        test::writeJpeg(QDir(photos).filePath(QStringLiteral("IMG_0103.JPG")), ++seed);
        {
            QFile f(QDir(photos).filePath(QStringLiteral("IMG_0104.JPG")));
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray(4096, '\x5a'));
        }
        QFile(QDir(photos).filePath(QStringLiteral("IMG_0105.JPG"))).open(QIODevice::WriteOnly);
        // Not a photo by its name: not counted.
        QFile(QDir(photos).filePath(QStringLiteral("readme.txt"))).open(QIODevice::WriteOnly);
        for (const QString &name : QDir(photos).entryList(QDir::Files))
            before[name] = test::sha256(QDir(photos).filePath(name));

        QString error;
        const auto track = readGpxTrack(gpx, &error);
        QVERIFY2(track, qPrintable(error));
        QCOMPARE(track->points.size(), points.size());
        GeotagOptions options;
        options.outFolder = out;
        options.match.offsetMs = offset;
        const auto report = geotagFolder(photos, *track, options, &error);
        QVERIFY2(report, qPrintable(error));
        QCOMPARE(report->photos, 13);
        QCOMPARE(int(report->tagged.size()), 7);
        QCOMPARE(report->offsetSeconds, 1.5);

        // Every copy holds the position the track gives at its time, read back with exiv2.
        std::vector<Shot> all = good;
        all.push_back({"IMG_0007.JPG", 20'000});
        for (const Shot &s : all) {
            const QString copy = QDir(out).filePath(QString::fromLatin1(s.name));
            QVERIFY2(QFile::exists(copy), s.name);
            const auto want = expectedAt(points, s.trackMs);
            const test::ReadBack got = test::readGps(copy);
            QVERIFY2(got.latitude && got.longitude && got.altitude, s.name);
            QVERIFY2(std::fabs(*got.latitude - want.lat) < 1e-6, qPrintable(QStringLiteral("%1: latitude %2, expected %3").arg(QString::fromLatin1(s.name)).arg(*got.latitude, 0, 'f', 9).arg(want.lat, 0, 'f', 9)));
            QVERIFY2(std::fabs(*got.longitude - want.lon) < 1e-6, qPrintable(QStringLiteral("%1: longitude %2, expected %3").arg(QString::fromLatin1(s.name)).arg(*got.longitude, 0, 'f', 9).arg(want.lon, 0, 'f', 9)));
            QVERIFY2(std::fabs(*got.altitude - want.ele) < 0.1, qPrintable(QStringLiteral("%1: altitude %2, expected %3").arg(QString::fromLatin1(s.name)).arg(*got.altitude).arg(want.ele)));
            QCOMPARE(got.latitudeRef, QStringLiteral("N"));
            QCOMPARE(got.longitudeRef, QStringLiteral("E"));
            QCOMPARE(got.altitudeRef, 0);
            QCOMPARE(got.datum, QStringLiteral("WGS-84"));
            QCOMPARE(got.version, QStringLiteral("2 3 0 0"));
            QCOMPARE(got.dateStamp, utcText(kTrackStart + s.trackMs));
            const QTime t = QDateTime::fromMSecsSinceEpoch(kTrackStart + s.trackMs, QTimeZone::utc()).time();
            QCOMPARE(got.timeStamp, QStringLiteral("%1:%2:%3").arg(t.hour(), 2, 10, QLatin1Char('0')).arg(t.minute(), 2, 10, QLatin1Char('0'))
                                        .arg(t.second() + t.msec() / 1000.0, 6, 'f', 3, QLatin1Char('0')));
            QVERIFY(!got.relativeAltitude); // a GPX has no height above take-off: none is written
            // The copy is still the camera's photo: its own tags are kept.
            const auto info = PhotoMetadataFile::read(copy, &error);
            QVERIFY2(info, qPrintable(error));
            QCOMPARE(info->model, QStringLiteral("Q-64"));
        }

        // The others are named, each with its reason, and have no copy.
        std::map<QString, QString> reasons;
        for (const UntaggedPhoto &u : report->untagged)
            reasons[u.file] = u.reason;
        QCOMPARE(int(reasons.size()), 6);
        QVERIFY2(reasons[QStringLiteral("IMG_0100.JPG")].contains(QStringLiteral("before the track starts")), qPrintable(reasons[QStringLiteral("IMG_0100.JPG")]));
        QVERIFY2(reasons[QStringLiteral("IMG_0100.JPG")].contains(QStringLiteral("4.0 s")), qPrintable(reasons[QStringLiteral("IMG_0100.JPG")]));
        QVERIFY2(reasons[QStringLiteral("IMG_0101.JPG")].contains(QStringLiteral("after the track ends")), qPrintable(reasons[QStringLiteral("IMG_0101.JPG")]));
        QVERIFY2(reasons[QStringLiteral("IMG_0102.JPG")].contains(QStringLiteral("gap of 20.0 s")), qPrintable(reasons[QStringLiteral("IMG_0102.JPG")]));
        QVERIFY2(reasons[QStringLiteral("IMG_0103.JPG")].contains(QStringLiteral("no capture time")), qPrintable(reasons[QStringLiteral("IMG_0103.JPG")]));
        QVERIFY2(reasons[QStringLiteral("IMG_0104.JPG")].contains(QStringLiteral("exiv2")), qPrintable(reasons[QStringLiteral("IMG_0104.JPG")]));
        QVERIFY2(reasons[QStringLiteral("IMG_0105.JPG")].contains(QStringLiteral("exiv2")), qPrintable(reasons[QStringLiteral("IMG_0105.JPG")]));
        for (const auto &[name, reason] : reasons)
            QVERIFY2(!QFile::exists(QDir(out).filePath(name)), qPrintable(name));

        // The originals are byte for byte as they were, and nothing was added beside them.
        QCOMPARE(int(QDir(photos).entryList(QDir::Files).size()), int(before.size()));
        for (const auto &[name, hash] : before)
            QVERIFY2(test::sha256(QDir(photos).filePath(name)) == hash, qPrintable(name + QStringLiteral(" changed")));

        // geo.txt (OpenDroneMap) and geotags.csv (Pix4D, Metashape), the tagged ones by name.
        QFile geo(QDir(out).filePath(QStringLiteral("geo.txt")));
        QVERIFY(geo.open(QIODevice::ReadOnly));
        const QStringList geoLines = QString::fromUtf8(geo.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(geoLines.value(0), QStringLiteral("EPSG:4326"));
        QCOMPARE(geoLines.size(), 8);
        const auto first = expectedAt(points, 0);
        QCOMPARE(geoLines.value(1), QStringLiteral("IMG_0001.JPG %1 %2 %3").arg(first.lon, 0, 'f', 8).arg(first.lat, 0, 'f', 8).arg(first.ele, 0, 'f', 3));
        QFile csv(QDir(out).filePath(QStringLiteral("geotags.csv")));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList csvLines = QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(csvLines.value(0), QStringLiteral("#name,latitude,longitude,altitude"));
        QCOMPARE(csvLines.size(), 8);
        QCOMPARE(csvLines.value(1), QStringLiteral("IMG_0001.JPG,%1,%2,%3").arg(first.lat, 0, 'f', 8).arg(first.lon, 0, 'f', 8).arg(first.ele, 0, 'f', 3));

        // The out folder may not be the photos' own.
        QVERIFY(!geotagFolder(photos, *track, GeotagOptions{photos, {}}, &error));
        QVERIFY2(error.contains(QStringLiteral("own folder")), qPrintable(error));
    }

    void positionsAcrossTheAntimeridianAndBelowTheSea()
    {
        Track track;
        track.points = {{0, -33.0, 179.9999, -2.0, std::nan("")}, {1000, -33.001, -179.9999, -4.0, std::nan("")}};
        QString reason;
        const auto p = positionAt(track, 500, 5000, &reason);
        QVERIFY2(p, qPrintable(reason));
        QVERIFY(std::fabs(std::fabs(p->longitude) - 180.0) < 1e-9);
        QVERIFY(std::fabs(p->latitude + 33.0005) < 1e-12);
        QCOMPARE(p->altitudeAmsl, std::optional<double>(-3.0));
        QVERIFY(!p->heightAboveTakeoff);

        QTemporaryDir dir;
        const QString copy = dir.filePath(QStringLiteral("south.jpg"));
        test::writeJpeg(copy, 9);
        QVERIFY2(PhotoMetadataFile::writeGeoTag(copy, {-33.0005, -179.25, -3.0, 12.5, 86'399'999}, &reason), qPrintable(reason));
        const auto got = test::readGps(copy);
        QCOMPARE(got.latitudeRef, QStringLiteral("S"));
        QCOMPARE(got.longitudeRef, QStringLiteral("W"));
        QVERIFY(std::fabs(*got.latitude + 33.0005) < 1e-9);
        QVERIFY(std::fabs(*got.longitude + 179.25) < 1e-9);
        QCOMPARE(got.altitudeRef, 1);
        QVERIFY(std::fabs(*got.altitude + 3.0) < 1e-9);
        QCOMPARE(got.relativeAltitude, std::optional<double>(12.5));
        QCOMPARE(got.timeStamp, QStringLiteral("23:59:59.999"));
        QCOMPARE(got.dateStamp, QStringLiteral("1970:01:01"));
    }

    // A JPEG with two damaged EXIF segments (found by fuzz_photo_metadata): exiv2 reads it, writes
    // the tags, and then refuses its own copy ("This does not look like a TIFF image"). The copy is
    // not called tagged; the reason says so.
    void aCopyThatDoesNotReadBackIsNoTaggedPhoto()
    {
        const QString damaged = QString::fromUtf8(sortieTestData()) + QStringLiteral("/photos/two-damaged-exif-segments.jpg");
        QVERIFY2(QFile::exists(damaged), qPrintable(damaged + QStringLiteral(" is missing")));
        QString reason;
        QVERIFY2(PhotoMetadataFile::read(damaged, &reason), qPrintable(reason));
        QTemporaryDir dir;
        const QString copy = dir.filePath(QStringLiteral("copy.jpg"));
        QVERIFY(QFile::copy(damaged, copy));
        QVERIFY(QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner));
        QVERIFY(!PhotoMetadataFile::writeGeoTag(copy, {56.95, 24.1, 40.0, 20.0, 0}, &reason));
        QVERIFY2(reason.contains(QStringLiteral("cannot read back")), qPrintable(reason));
    }

    void badGpxNamesItsLine()
    {
        QTemporaryDir dir;
        struct Case { const char *text; const char *expect; };
        const std::vector<Case> cases{
            {"<gpx version=\"1.1\">\n<trk><trkseg>\n<trkpt lat=\"56.9\" lon=\"24.1\"><time>2026-05-01T10:00:00Z</time></trkpt>\n<trkpt lat=\"95\" lon=\"24.1\"><time>2026-05-01T10:00:01Z</time></trkpt>\n</trkseg></trk></gpx>\n", ":4: a track point needs lat"},
            {"<gpx version=\"1.1\">\n<trk><trkseg>\n<trkpt lat=\"56.9\" lon=\"24.1\"><ele>40</ele></trkpt>\n</trkseg></trk></gpx>\n", ":3: the track point has no <time>"},
            {"<gpx version=\"1.1\">\n<trk><trkseg>\n<trkpt lat=\"56.9\" lon=\"24.1\">\n<time>yesterday</time></trkpt>\n</trkseg></trk></gpx>\n", ":4: <time> \"yesterday\""},
            {"<gpx version=\"1.1\">\n<trk><trkseg>\n<trkpt lat=\"56.9\" lon=\"24.1\"><ele>high</ele><time>2026-05-01T10:00:00Z</time></trkpt>\n</trkseg></trk></gpx>\n", ":3: <ele> \"high\""},
            {"<gpx version=\"1.1\">\n<trk><trkseg>\n<trkpt lat=\"56.9\" lon=\"24.1\"><time>2026-05-01T10:00:00Z</time>\n</trkseg></trk></gpx>\n", ":4"},
            {"<kml>\n</kml>\n", "is not a GPX file"},
            {"<gpx version=\"1.1\">\n<wpt lat=\"56.9\" lon=\"24.1\"/>\n</gpx>\n", "holds no track points"},
        };
        int n = 0;
        for (const Case &c : cases) {
            const QString path = dir.filePath(QStringLiteral("bad%1.gpx").arg(++n));
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(c.text);
            f.close();
            QString error;
            QVERIFY2(!readGpxTrack(path, &error), c.expect);
            QVERIFY2(error.startsWith(path), qPrintable(error));
            QVERIFY2(error.contains(QString::fromLatin1(c.expect)), qPrintable(error + QStringLiteral(" lacks ") + QString::fromLatin1(c.expect)));
        }
        // A time with a zone, and one without (UTC, as GPX says).
        const QString path = dir.filePath(QStringLiteral("zones.gpx"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("<gpx version=\"1.0\"><trk><trkseg>"
                "<trkpt lat=\"1\" lon=\"2\"><time>2026-05-01T12:00:01.5+02:00</time></trkpt>"
                "<trkpt lat=\"1\" lon=\"2\"><time>2026-05-01T10:00:00</time></trkpt>"
                "</trkseg></trk></gpx>");
        f.close();
        QString error;
        const auto track = readGpxTrack(path, &error);
        QVERIFY2(track, qPrintable(error));
        QCOMPARE(track->points.size(), size_t(2));
        QCOMPARE(track->points[0].time, kTrackStart);        // sorted by time
        QCOMPARE(track->points[1].time, kTrackStart + 1500);
        QVERIFY(std::isnan(track->points[0].altitudeAmsl));   // no <ele>: missing, not 0
    }

    void flightLogTrackGivesHeightAboveTakeoff()
    {
        QTemporaryDir dir;
        const QString log = dir.filePath(QStringLiteral("flight.sortielog"));
        // Vehicle A at 10 Hz for 20 s, climbing; AGL sent every other sample only. B elsewhere.
        test::LoggedVehicle a{QStringLiteral("VCI:a"), QStringLiteral("EMU-101"), {}}, b{QStringLiteral("VCI:b"), QStringLiteral("EMU-102"), {}};
        for (int i = 0; i <= 200; ++i) {
            const double t = i * 100.0;
            a.samples.push_back({t, 56.95 + 1e-6 * i + 2e-9 * i * i, 24.10 + 3e-6 * i, 30 + 0.1 * i, i % 2 == 0 ? 10 + 0.1 * i : std::nan("")});
            b.samples.push_back({t, 57.10, 24.30 - 1e-6 * i, 50, 20});
        }
        QCOMPARE(test::writeFlightLog(log, {a, b}), QString());
        QString error;
        const auto opened = flightlog::FlightLog::open(log, &error);
        QVERIFY2(opened, qPrintable(error));
        QCOMPARE(int(opened->vehicles().size()), 2);
        const int vehicle = opened->vehicleIndex(QStringLiteral("EMU-101"));
        QVERIFY(vehicle >= 0);
        const auto track = flightLogTrack(*opened, vehicle, &error);
        QVERIFY2(track, qPrintable(error));
        QCOMPARE(track->points.size(), size_t(201));

        // Photos at 2.55 s and 13.37 s: between samples, interpolated; the copy carries the height above take-off.
        const QString photos = dir.filePath(QStringLiteral("card")), out = dir.filePath(QStringLiteral("out"));
        QVERIFY(QDir().mkpath(photos));
        for (const auto &[name, ms] : std::vector<std::pair<QString, int64_t>>{{QStringLiteral("a.jpg"), 2550}, {QStringLiteral("b.jpg"), 13'370}}) {
            test::writeJpeg(QDir(photos).filePath(name), int(ms));
            test::setCameraTags(QDir(photos).filePath(name), test::takenAt(ms));
        }
        const auto report = geotagFolder(photos, *track, {out, {}}, &error);
        QVERIFY2(report, qPrintable(error));
        QCOMPARE(int(report->tagged.size()), 2);
        for (const auto &[name, ms] : std::vector<std::pair<QString, int64_t>>{{QStringLiteral("a.jpg"), 2550}, {QStringLiteral("b.jpg"), 13'370}}) {
            const double i = double(ms) / 100.0; // the sample index, fractional
            const int i0 = int(std::floor(i));
            const double f = i - i0;
            auto lat = [](int k) { return 56.95 + 1e-6 * k + 2e-9 * k * k; };
            const double wantLat = lat(i0) + f * (lat(i0 + 1) - lat(i0));
            const double wantLon = 24.10 + 3e-6 * i;
            const double wantAmsl = 30 + 0.1 * i, wantAgl = 10 + 0.1 * i;
            const auto got = test::readGps(QDir(out).filePath(name));
            QVERIFY2(got.latitude && std::fabs(*got.latitude - wantLat) < 1e-6, qPrintable(name));
            QVERIFY2(got.longitude && std::fabs(*got.longitude - wantLon) < 1e-6, qPrintable(name));
            QVERIFY2(got.altitude && std::fabs(*got.altitude - wantAmsl) < 0.1, qPrintable(name));
            QVERIFY2(got.relativeAltitude && std::fabs(*got.relativeAltitude - wantAgl) < 0.1,
                     qPrintable(QStringLiteral("%1: relative altitude %2, expected %3").arg(name).arg(got.relativeAltitude.value_or(-1)).arg(wantAgl)));
        }
    }

    // The heading a log holds, between its samples the short way round; else the course flown.
    void headingFromTheLogElseTheCourse()
    {
        QTemporaryDir dir;
        const QString log = dir.filePath(QStringLiteral("turning.sortielog"));
        // 20 s east at 5 m/s, then 20 s hovering; the nose swings from 350° through north to 10°.
        test::LoggedVehicle a{QStringLiteral("VCI:a"), QStringLiteral("EMU-101"), {}};
        for (int i = 0; i <= 400; ++i) {
            const double t = i * 100.0, east = std::min(t, 20'000.0) / 1000.0 * 5.0;
            a.samples.push_back({t, 56.95, 24.10 + east / (111'195.0 * std::cos(56.95 * std::numbers::pi / 180)), 60, 20});
        }
        a.headings = {{0, 350}, {10'000, 10}, {30'000, 10}};
        QCOMPARE(test::writeFlightLog(log, {a}), QString());
        QString error;
        const auto opened = flightlog::FlightLog::open(log, &error);
        QVERIFY2(opened, qPrintable(error));
        // The log's samples are 10 s apart: bridged when the track is read with a 10 s gap.
        const auto track = flightLogTrack(*opened, 0, &error, 10'000);
        QVERIFY2(track, qPrintable(error));
        const auto at5 = positionAt(*track, test::kTrackStart + 5'000, 5000, &error);
        QVERIFY2(at5 && at5->heading, qPrintable(error));
        QVERIFY2(std::fabs(*at5->heading - 0) < 0.01 || std::fabs(*at5->heading - 360) < 0.01, qPrintable(QString::number(*at5->heading)));
        const auto at2 = positionAt(*track, test::kTrackStart + 2'500, 5000, &error);
        QVERIFY(at2 && at2->heading && std::fabs(*at2->heading - 355) < 0.01);
        // The course: east while flying, none while hovering, none off the track.
        const auto course = courseAt(*track, test::kTrackStart + 10'000, 5000);
        QVERIFY(course);
        QVERIFY2(std::fabs(*course - 90) < 0.5, qPrintable(QString::number(*course)));
        QVERIFY(!courseAt(*track, test::kTrackStart + 30'000, 5000));
        QVERIFY(!courseAt(*track, test::kTrackStart + 60'000, 5000));
        // Without a heading in the log the position has none (missing, never 0).
        test::LoggedVehicle b{QStringLiteral("VCI:b"), QStringLiteral("EMU-102"), a.samples};
        const QString plain = dir.filePath(QStringLiteral("plain.sortielog"));
        QCOMPARE(test::writeFlightLog(plain, {b}), QString());
        const auto plainLog = flightlog::FlightLog::open(plain, &error);
        QVERIFY2(plainLog, qPrintable(error));
        const auto plainTrack = flightLogTrack(*plainLog, 0, &error);
        QVERIFY(plainTrack);
        const auto p = positionAt(*plainTrack, test::kTrackStart + 5'000, 5000, &error);
        QVERIFY(p && !p->heading);
    }

    // A survey's shutter events and the card's photos: the camera's clock an hour and some off, its
    // times in whole hundredths; two events without a photo (frames lost), three test shots on the
    // ground before take-off and one stray photo between two events.
    void pairsPhotosWithTheFlightsPhotoEvents()
    {
        std::vector<int64_t> events, photos;
        const int64_t offset = 3'723'400; // the vehicle's clock minus the camera's
        for (int i = 0; i < 100; ++i)
            events.push_back(kTrackStart + i * 2000 + (i * 7919) % 300 - 150); // 2 s apart, ±150 ms
        for (int64_t t : {kTrackStart - 60'000, kTrackStart - 50'000, kTrackStart - 40'000})
            photos.push_back(t - offset);
        for (int i = 0; i < 100; ++i)
            if (i != 10 && i != 55)
                photos.push_back((events[size_t(i)] - offset + 40) / 10 * 10); // the shutter's latency, hundredths
        photos.push_back(events[70] + 1000 - offset);
        std::sort(photos.begin(), photos.end());
        const auto pairing = pairWithEvents(photos, events);
        QVERIFY(pairing);
        QVERIFY2(std::llabs(pairing->offsetMs + 40 - offset) <= 10, qPrintable(QString::number(pairing->offsetMs)));
        QCOMPARE(pairing->pairs.size(), size_t(98));
        QCOMPARE(pairing->unpairedEvents, (std::vector<size_t>{10, 55}));
        QCOMPARE(pairing->unpairedPhotos.size(), size_t(4));
        for (const auto &[photo, event] : pairing->pairs)
            QVERIFY(std::llabs(photos[photo] + pairing->offsetMs - events[event]) <= pairing->toleranceMs);
        // One photo is no pattern; none, nothing to pair.
        QVERIFY(!pairWithEvents({photos[5]}, events));
        QVERIFY(!pairWithEvents({}, events));
    }

    // With the track's photo events, each photo goes where the vehicle said it took it; an event
    // without a photo is listed, a photo without one named. By time when asked.
    void placesPhotosByTheirEvents()
    {
        Track track;
        track.source = QStringLiteral("flight.sortielog");
        for (int s = 0; s <= 40; ++s)
            track.points.push_back({kTrackStart + s * 1000, 56.95 + 1e-5 * s, 24.10, 100, 60, 90});
        for (int i = 0; i < 10; ++i)
            track.photos.push_back({kTrackStart + 5000 + i * 3000, i + 1, 56.95 + 1e-5 * (5 + 3 * i) + 2e-7, 24.10 + 3e-7, 100.5, 91, 90});
        std::vector<PhotoInfo> photos;
        const int64_t cameraBehind = 7'200'000 + 250; // two hours and a quarter second
        for (int i = 0; i < 10; ++i) {
            if (i == 4)
                continue; // frame lost
            PhotoInfo p;
            p.fileName = QStringLiteral("DSC_%1.JPG").arg(i + 1);
            p.cameraTimeUtc = track.photos[size_t(i)].time - cameraBehind;
            photos.push_back(p);
        }
        PhotoInfo ground;
        ground.fileName = QStringLiteral("TEST.JPG");
        ground.cameraTimeUtc = kTrackStart - 120'000 - cameraBehind;
        photos.insert(photos.begin(), ground);

        const GeotagReport report = matchPhotos(photos, track, {});
        QVERIFY(report.byEvents);
        QCOMPARE(report.offsetSeconds, 7200.25);
        QCOMPARE(report.missing, (std::vector<int64_t>{5}));
        QCOMPARE(report.tagged.size(), size_t(9));
        QCOMPARE(report.untagged.size(), size_t(1));
        QCOMPARE(report.untagged.front().file, QStringLiteral("TEST.JPG"));
        QVERIFY(report.untagged.front().reason.contains(QLatin1String("no photo the vehicle reported")));
        for (const TaggedPhoto &t : report.tagged) {
            const int n = t.photo.fileName.mid(4, t.photo.fileName.indexOf(u'.') - 4).toInt();
            const TrackPhoto &event = track.photos[size_t(n - 1)];
            QCOMPARE(t.time, event.time);
            QCOMPARE(t.position.latitude, event.latitude);  // the vehicle's own, not the track's
            QCOMPARE(t.position.longitude, event.longitude);
            QCOMPARE(t.position.altitudeAmsl, std::optional(100.5));
            QCOMPARE(t.position.heading, std::optional(91.0));
            QCOMPARE(t.position.heightAboveTakeoff, std::optional(60.0)); // from the track at that moment
        }
        const QJsonObject json = report.toJson();
        QCOMPARE(json.value(QStringLiteral("matchedBy")).toString(), QStringLiteral("events"));
        // The copies carry the vehicle's position and the gimbal's pitch (tilt 90: -90, down).
        QTemporaryDir dir;
        GeotagReport written = report;
        written.tagged.resize(2);
        for (TaggedPhoto &t : written.tagged) {
            t.photo.path = dir.filePath(t.photo.fileName);
            test::writeJpeg(t.photo.path, 1);
        }
        QVERIFY(QDir().mkpath(dir.filePath(QStringLiteral("out"))));
        QString error;
        QVERIFY2(writeGeotagged(written, dir.filePath(QStringLiteral("out")), &error), qPrintable(error));
        QCOMPARE(written.tagged.size(), size_t(2));
        const auto back = test::readGps(dir.filePath(QStringLiteral("out/")) + written.tagged[0].photo.fileName);
        QVERIFY(back.latitude && std::fabs(*back.latitude - written.tagged[0].position.latitude) < 1e-7);
        QCOMPARE(back.gimbalPitch, std::optional(-90.0));
        QCOMPARE(back.relativeAltitude, std::optional(60.0));
        QCOMPARE(json.value(QStringLiteral("missing")).toArray().size(), 1);

        // By time, as asked: the camera's clock is two hours behind the track, so nothing is on it.
        MatchOptions byTime;
        byTime.byEvents = false;
        const GeotagReport timed = matchPhotos(photos, track, byTime);
        QVERIFY(!timed.byEvents);
        QCOMPARE(timed.tagged.size(), size_t(0));
        byTime.offsetMs = cameraBehind;
        QCOMPARE(matchPhotos(photos, track, byTime).tagged.size(), size_t(9));
    }
};

QTEST_GUILESS_MAIN(TestGeotag)
#include "tst_geotag.moc"
