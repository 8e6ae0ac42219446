#include "PhotoEvents.h"

#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace sortie::flightlog {

namespace {

void put(QJsonObject &o, const char *key, double value)
{
    if (std::isfinite(value))
        o.insert(QLatin1String(key), value);
}

double read(const QJsonObject &o, const char *key)
{
    const QJsonValue v = o.value(QLatin1String(key));
    return v.isDouble() && std::isfinite(v.toDouble()) ? v.toDouble() : qQNaN();
}

} // namespace

QString photoEventText(const vehicle::CameraPhoto &photo)
{
    QJsonObject o{{QStringLiteral("sequence"), photo.sequence}};
    put(o, "latitude", photo.latitude);
    put(o, "longitude", photo.longitude);
    put(o, "altitudeAmsl", photo.altitudeAmsl);
    put(o, "altitudeAgl", photo.altitudeAgl);
    put(o, "roll", photo.roll);
    put(o, "pitch", photo.pitch);
    put(o, "yaw", photo.yaw);
    put(o, "gimbalTilt", photo.gimbalTilt);
    return QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact));
}

std::optional<vehicle::CameraPhoto> photoOfEvent(const FlightLog::Event &event)
{
    if (event.kind != QLatin1String(kPhotoEventKind))
        return std::nullopt;
    const QJsonDocument doc = QJsonDocument::fromJson(event.text.toUtf8());
    if (!doc.isObject())
        return std::nullopt;
    const QJsonObject o = doc.object();
    vehicle::CameraPhoto p;
    const double sequence = read(o, "sequence");
    p.latitude = read(o, "latitude");
    p.longitude = read(o, "longitude");
    if (!(sequence >= 1 && sequence < 9e15) || !(std::abs(p.latitude) <= 90) || !(std::abs(p.longitude) <= 180))
        return std::nullopt;
    p.sequence = qint64(sequence);
    p.time = event.time;
    p.altitudeAmsl = read(o, "altitudeAmsl");
    p.altitudeAgl = read(o, "altitudeAgl");
    p.roll = read(o, "roll");
    p.pitch = read(o, "pitch");
    p.yaw = read(o, "yaw");
    p.gimbalTilt = read(o, "gimbalTilt");
    return p;
}

std::vector<vehicle::CameraPhoto> photosOf(const FlightLog &log, int vehicle)
{
    std::vector<vehicle::CameraPhoto> photos;
    for (const FlightLog::Event &e : log.events())
        if (e.vehicle == vehicle)
            if (auto p = photoOfEvent(e))
                photos.push_back(*p);
    return photos;
}

} // namespace sortie::flightlog
