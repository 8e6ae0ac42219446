#include "FlightLogInfo.h"

#include <QDateTime>
#include <QJsonArray>
#include <QCoreApplication>

namespace sortie::flightlog {

namespace {
QString utc(int64_t ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs);
}
QString name(std::string_view s)
{
    return QString::fromLatin1(s.data(), qsizetype(s.size()));
}
} // namespace

QJsonObject logInfoJson(const FlightLog &log)
{
    QJsonArray vehicles;
    for (const FlightLog::Vehicle &v : log.vehicles()) {
        QJsonObject fields;
        for (size_t f = 0; f < vehicle::kTelemetryFieldCount; ++f) {
            if (v.counts[f])
                fields.insert(name(vehicle::fieldName(vehicle::TelemetryField(f))), qint64(v.counts[f]));
        }
        QJsonArray missions;
        for (const FlightLog::Mission &m : v.missions)
            missions.append(QJsonObject{{"time", utc(m.time)}, {"waypoints", int(m.items.size())}});
        QJsonObject o{{"key", v.key}, {"name", v.name()}, {"protocol", v.identity.protocol}, {"type", v.identity.type},
                      {"autopilot", v.identity.autopilot}, {"samples", qint64(v.sampleCount())}, {"fields", fields},
                      {"routes", missions}};
        if (v.sampleCount()) {
            o.insert(QStringLiteral("start"), utc(v.start));
            o.insert(QStringLiteral("end"), utc(v.end));
        }
        vehicles.append(o);
    }
    QJsonArray events;
    for (const FlightLog::Event &e : log.events()) {
        QJsonObject o{{"time", utc(e.time)}, {"kind", e.kind}, {"text", e.text}};
        if (e.vehicle >= 0)
            o.insert(QStringLiteral("vehicle"), log.vehicles()[size_t(e.vehicle)].name());
        if (e.ok >= 0)
            o.insert(QStringLiteral("ok"), e.ok == 1);
        events.append(o);
    }
    QJsonObject info{{"file", log.path()}, {"vehicles", vehicles}, {"events", events},
                     {"complete", log.damage().isEmpty()}};
    if (log.end() > 0) {
        info.insert(QStringLiteral("start"), utc(log.start()));
        info.insert(QStringLiteral("end"), utc(log.end()));
        info.insert(QStringLiteral("seconds"), double(log.end() - log.start()) / 1000.0);
    }
    if (!log.stoppedAt().isEmpty())
        info.insert(QStringLiteral("stoppedAt"), log.stoppedAt());
    if (!log.skipped().isEmpty())
        info.insert(QStringLiteral("skipped"), QJsonArray::fromStringList(log.skipped()));
    return info;
}

QString logInfoText(const FlightLog &log)
{
    QString out;
    out += QObject::tr("file:     %1\n").arg(log.path());
    if (log.end() > 0)
        out += QObject::tr("span:     %1 to %2 (%3 s)\n").arg(utc(log.start()), utc(log.end())).arg(double(log.end() - log.start()) / 1000.0, 0, 'f', 1);
    if (!log.stoppedAt().isEmpty())
        out += QObject::tr("DAMAGED:  read up to the last good record; %1\n").arg(log.stoppedAt());
    for (const QString &skipped : log.skipped())
        out += QObject::tr("DAMAGED:  %1\n").arg(skipped);
    out += QObject::tr("vehicles: %1\n").arg(log.vehicles().size());
    for (const FlightLog::Vehicle &v : log.vehicles()) {
        out += QCoreApplication::translate("FlightLogInfo", "\n  %1 (%2%3%4): %5 samples").arg(v.name(), v.identity.protocol,
                                                                v.identity.type.isEmpty() ? QString() : QStringLiteral(", ") + v.identity.type,
                                                                v.identity.autopilot.isEmpty() ? QString() : QStringLiteral(", ") + v.identity.autopilot)
                   .arg(v.sampleCount());
        if (v.sampleCount())
            out += QObject::tr(", %1 to %2").arg(utc(v.start), utc(v.end));
        out += QLatin1Char('\n');
        for (size_t f = 0; f < vehicle::kTelemetryFieldCount; ++f) {
            if (v.counts[f])
                out += QStringLiteral("    %1 %2\n").arg(name(vehicle::fieldName(vehicle::TelemetryField(f))), -18).arg(v.counts[f]);
        }
        for (const FlightLog::Mission &m : v.missions)
            out += QObject::tr("    route uploaded %1: %2 waypoints\n").arg(utc(m.time)).arg(m.items.size());
    }
    out += QObject::tr("\nevents:   %1\n").arg(log.events().size());
    for (const FlightLog::Event &e : log.events()) {
        out += QStringLiteral("  %1  %2  %3%4%5\n").arg(utc(e.time), e.kind.leftJustified(8),
                                                       e.vehicle >= 0 ? log.vehicles()[size_t(e.vehicle)].name() + QStringLiteral(": ") : QString(),
                                                       e.text, e.ok == 0 ? QObject::tr(" (failed)") : QString());
    }
    return out;
}

} // namespace sortie::flightlog
