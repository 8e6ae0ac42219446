#include "Track.h"

#include "FlightLog.h"
#include "GeotagLog.h"
#include "PhotoEvents.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTimeZone>
#include <QXmlStreamReader>

#include <algorithm>
#include <cmath>

namespace sortie::geotag {

using vehicle::TelemetryField;
using vehicle::TelemetrySample;

void Track::normalise()
{
    std::stable_sort(points.begin(), points.end(), [](const TrackPoint &a, const TrackPoint &b) { return a.time < b.time; });
    std::vector<TrackPoint> unique;
    unique.reserve(points.size());
    for (const TrackPoint &p : points) {
        if (!unique.empty() && unique.back().time == p.time)
            unique.back() = p;
        else
            unique.push_back(p);
    }
    points = std::move(unique);
}

namespace {

QString where(const QString &path, qint64 line)
{
    return QStringLiteral("%1:%2").arg(path).arg(line);
}

// GPX times: xsd:dateTime, UTC when no zone is given.
std::optional<int64_t> gpxTime(const QString &text)
{
    static const QRegularExpression re(QStringLiteral(
        "^(\\d{4})-(\\d{2})-(\\d{2})T(\\d{2}):(\\d{2}):(\\d{2})(?:\\.(\\d+))?(Z|[+-]\\d{2}:\\d{2})?$"));
    const auto m = re.match(text.trimmed());
    if (!m.hasMatch())
        return std::nullopt;
    const QDate date(m.captured(1).toInt(), m.captured(2).toInt(), m.captured(3).toInt());
    const QTime time(m.captured(4).toInt(), m.captured(5).toInt(), m.captured(6).toInt());
    if (!date.isValid() || !time.isValid())
        return std::nullopt;
    int64_t ms = QDateTime(date, time, QTimeZone::utc()).toMSecsSinceEpoch();
    if (!m.captured(7).isEmpty())
        ms += std::llround((m.captured(7).left(9) + QStringLiteral("000000000")).left(9).toLongLong() / 1e6);
    const QString zone = m.captured(8);
    if (!zone.isEmpty() && zone != QLatin1String("Z")) {
        const int hours = zone.mid(1, 2).toInt(), minutes = zone.mid(4, 2).toInt();
        if (hours > 14 || minutes > 59)
            return std::nullopt;
        const int seconds = hours * 3600 + minutes * 60;
        ms -= int64_t(zone.startsWith(QLatin1Char('-')) ? -seconds : seconds) * 1000;
    }
    return ms;
}

std::optional<double> coordinate(const QStringView text, double limit)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v) || std::fabs(v) > limit)
        return std::nullopt;
    return v;
}

// The value of a sampled field at `t`, between the samples around it when they are at most maxGap
// apart (the sample itself when one is at t), by `mix(before, after, fraction)`; NaN otherwise.
template<class Mix>
double sampledAt(const std::vector<TelemetrySample> &series, int64_t t, int64_t maxGap, Mix mix)
{
    const auto after = std::lower_bound(series.begin(), series.end(), t, [](const TelemetrySample &s, int64_t time) { return s.time < time; });
    if (after != series.end() && after->time == t)
        return after->value;
    if (after == series.begin() || after == series.end())
        return std::nan("");
    const auto before = after - 1;
    if (after->time - before->time > maxGap || std::isnan(before->value) || std::isnan(after->value))
        return std::nan("");
    return mix(before->value, after->value, double(t - before->time) / double(after->time - before->time));
}

// Linear.
double valueAt(const std::vector<TelemetrySample> &series, int64_t t, int64_t maxGap)
{
    return sampledAt(series, t, maxGap, [](double a, double b, double f) { return a + f * (b - a); });
}

// A heading, the short way round (359° and 1° meet at 0°).
double headingAt(const std::vector<TelemetrySample> &series, int64_t t, int64_t maxGap)
{
    return sampledAt(series, t, maxGap, [](double a, double b, double f) {
        const double h = std::fmod(a + f * std::remainder(b - a, 360.0), 360.0);
        return h < 0 ? h + 360 : h;
    });
}

// The last value at or before t (the home's altitude holds until it is reported again).
double lastAt(const std::vector<TelemetrySample> &series, int64_t t)
{
    const auto after = std::upper_bound(series.begin(), series.end(), t, [](int64_t time, const TelemetrySample &s) { return time < s.time; });
    return after == series.begin() ? std::nan("") : (after - 1)->value;
}

} // namespace

std::optional<Track> readGpxTrack(const QString &path, QString *error)
{
    auto fail = [&](const QString &message) -> std::optional<Track> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(path + QStringLiteral(": ") + file.errorString());
    QXmlStreamReader xml(&file);
    Track track;
    track.source = path;
    bool sawGpx = false;
    // The point being read: where it started, and what it has so far.
    bool inPoint = false;
    qint64 pointLine = 0;
    TrackPoint point;
    bool pointHasTime = false;
    while (!xml.atEnd()) {
        const auto token = xml.readNext();
        if (token == QXmlStreamReader::StartElement) {
            const QStringView name = xml.name();
            if (!sawGpx) {
                if (name != QLatin1String("gpx"))
                    return fail(QCoreApplication::translate("Geotag", "%1 is not a GPX file (its root element is <%2>, not <gpx>)")
                                    .arg(where(path, xml.lineNumber()), name.toString()));
                sawGpx = true;
                continue;
            }
            if (name == QLatin1String("trkpt")) {
                inPoint = true;
                pointLine = xml.lineNumber();
                point = TrackPoint{};
                pointHasTime = false;
                const auto attributes = xml.attributes();
                const auto lat = coordinate(attributes.value(QStringLiteral("lat")), 90);
                const auto lon = coordinate(attributes.value(QStringLiteral("lon")), 180);
                if (!lat || !lon)
                    return fail(QCoreApplication::translate("Geotag", "%1: a track point needs lat (-90 to 90) and lon (-180 to 180) in degrees, not lat=\"%2\" lon=\"%3\"")
                                    .arg(where(path, pointLine), attributes.value(QStringLiteral("lat")).toString(),
                                         attributes.value(QStringLiteral("lon")).toString()));
                point.latitude = *lat;
                point.longitude = *lon;
            } else if (inPoint && name == QLatin1String("ele")) {
                const qint64 line = xml.lineNumber();
                const QString text = xml.readElementText();
                if (xml.hasError())
                    break;
                bool ok = false;
                const double ele = text.trimmed().toDouble(&ok);
                if (!ok || !std::isfinite(ele) || std::fabs(ele) > 100000)
                    return fail(QCoreApplication::translate("Geotag", "%1: <ele> \"%2\" is no elevation in metres").arg(where(path, line), text));
                point.altitudeAmsl = ele;
            } else if (inPoint && name == QLatin1String("time")) {
                const qint64 line = xml.lineNumber();
                const QString text = xml.readElementText();
                if (xml.hasError())
                    break;
                const auto time = gpxTime(text);
                if (!time)
                    return fail(QCoreApplication::translate("Geotag", "%1: <time> \"%2\" is no UTC time (YYYY-MM-DDThh:mm:ssZ)").arg(where(path, line), text));
                point.time = *time;
                pointHasTime = true;
            } else if (inPoint) {
                xml.skipCurrentElement(); // extensions, hdop, sat, name...
            }
        } else if (token == QXmlStreamReader::EndElement && inPoint && xml.name() == QLatin1String("trkpt")) {
            inPoint = false;
            if (!pointHasTime)
                return fail(QCoreApplication::translate("Geotag", "%1: the track point has no <time>, so no photo can be matched to it").arg(where(path, pointLine)));
            track.points.push_back(point);
        }
    }
    if (xml.hasError())
        return fail(QCoreApplication::translate("Geotag", "%1 is not a readable GPX file: %2").arg(where(path, xml.lineNumber()), xml.errorString()));
    if (!sawGpx)
        return fail(QCoreApplication::translate("Geotag", "%1 is not a GPX file (no <gpx> element)").arg(path));
    if (track.points.empty())
        return fail(QCoreApplication::translate("Geotag", "%1 holds no track points (<trkpt>)").arg(path));
    track.normalise();
    qCInfo(lcGeotag).noquote() << path << ":" << track.points.size() << "track points";
    return track;
}

std::optional<Track> flightLogTrack(const flightlog::FlightLog &log, int vehicle, QString *error, int64_t maxGapMs)
{
    if (vehicle < 0 || size_t(vehicle) >= log.vehicles().size()) {
        if (error)
            *error = QCoreApplication::translate("Geotag", "%1 has no such vehicle").arg(log.path());
        return std::nullopt;
    }
    const auto lat = log.series(vehicle, TelemetryField::Latitude);
    const auto lon = log.series(vehicle, TelemetryField::Longitude);
    const auto amsl = log.series(vehicle, TelemetryField::AltitudeAmsl);
    const auto agl = log.series(vehicle, TelemetryField::AltitudeAgl);
    const auto home = log.series(vehicle, TelemetryField::HomeAltitudeAmsl);
    const auto heading = log.series(vehicle, TelemetryField::Heading);
    Track track;
    track.source = log.path();
    track.points.reserve(lat.size());
    for (const TelemetrySample &s : lat) {
        const double longitude = valueAt(lon, s.time, maxGapMs);
        if (std::isnan(s.value) || std::isnan(longitude))
            continue;
        TrackPoint p;
        p.time = s.time;
        p.latitude = s.value;
        p.longitude = longitude;
        p.altitudeAmsl = valueAt(amsl, s.time, maxGapMs);
        p.heightAboveTakeoff = valueAt(agl, s.time, maxGapMs);
        p.heading = headingAt(heading, s.time, maxGapMs);
        if (std::isnan(p.heightAboveTakeoff) && !std::isnan(p.altitudeAmsl))
            p.heightAboveTakeoff = p.altitudeAmsl - lastAt(home, s.time); // NaN while no home is known
        track.points.push_back(p);
    }
    if (track.points.empty()) {
        if (error)
            *error = QCoreApplication::translate("Geotag", "%1: vehicle %2 reported no position").arg(log.path(), log.vehicles()[size_t(vehicle)].name());
        return std::nullopt;
    }
    for (const vehicle::CameraPhoto &photo : flightlog::photosOf(log, vehicle))
        track.photos.push_back({photo.time, photo.sequence, photo.latitude, photo.longitude, photo.altitudeAmsl, photo.yaw, photo.gimbalTilt});
    std::stable_sort(track.photos.begin(), track.photos.end(), [](const TrackPhoto &a, const TrackPhoto &b) { return a.time < b.time; });
    track.normalise();
    qCInfo(lcGeotag).noquote() << log.path() << log.vehicles()[size_t(vehicle)].name() << ":" << track.points.size() << "positions,"
                               << track.photos.size() << "photo events";
    return track;
}

bool looksLikeFlightLog(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return QFileInfo(path).suffix().compare(QLatin1String("gpx"), Qt::CaseInsensitive) != 0;
    return file.read(16) == QByteArray("SQLite format 3\0", 16); // i18n: not text (SQLite's file header)
}

} // namespace sortie::geotag
