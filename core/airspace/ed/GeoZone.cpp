#include "GeoZone.h"

#include <QCoreApplication>
#include <QLocale>

#include <algorithm>

namespace sortie::airspace::ed {

namespace {
constexpr qint64 kDayMs = 86400000;
constexpr int kDaySeconds = 86400;

qint64 floorDiv(qint64 a, qint64 b)
{
    return a / b - ((a % b != 0) && ((a < 0) != (b < 0)));
}

// Monday 0 ... Sunday 6 of the UTC day `day` (days since 1970-01-01, a Thursday).
int weekday(qint64 day)
{
    return int(((day + 3) % 7 + 7) % 7);
}

bool periodApplies(const TimePeriod &p, qint64 from, qint64 to)
{
    if (p.permanent)
        return true;
    if (p.start)
        from = std::max(from, p.start->toMSecsSinceEpoch());
    if (p.end)
        to = std::min(to, p.end->toMSecsSinceEpoch());
    if (from > to)
        return false;
    if (p.schedule.empty())
        return true;
    // A daily period may begin the day before (overnight, or moved back by its offset): start two
    // days early. Over more than a week every weekday comes round.
    const qint64 first = floorDiv(from, kDayMs) - 2, last = floorDiv(to, kDayMs) + 1;
    if (last - first > 10)
        return std::any_of(p.schedule.begin(), p.schedule.end(), [](const DailyPeriod &d) { return d.days != 0; });
    for (qint64 day = first; day <= last; ++day) {
        const int wd = weekday(day);
        for (const DailyPeriod &d : p.schedule) {
            if (!(d.days & (1u << wd)))
                continue;
            const qint64 s = day * kDayMs + qint64(d.start) * 1000;
            const qint64 e = day * kDayMs + qint64(d.end + (d.overnight ? kDaySeconds : 0)) * 1000;
            if (s <= to && e >= from)
                return true;
        }
    }
    return false;
}

QString dayNames(std::uint8_t days)
{
    if ((days & 0x7f) == 0x7f)
        return QCoreApplication::translate("GeoZone", "daily");
    QStringList names;
    for (int d = 0; d < 7; ++d)
        if (days & (1u << d))
            names << QLocale().dayName(d + 1, QLocale::ShortFormat);
    return names.join(QLatin1Char(' '));
}

QString clock(int seconds)
{
    seconds = ((seconds % kDaySeconds) + kDaySeconds) % kDaySeconds;
    return QStringLiteral("%1:%2").arg(seconds / 3600, 2, 10, QLatin1Char('0')).arg(seconds / 60 % 60, 2, 10, QLatin1Char('0'));
}

// The days rotated by whole days (a period moved over midnight by the time zone's offset).
std::uint8_t rotated(std::uint8_t days, int by)
{
    by = ((by % 7) + 7) % 7;
    const unsigned d = days & 0x7f;
    return std::uint8_t(((d << by) | (d >> (7 - by))) & 0x7f);
}
} // namespace

QString restrictionName(Restriction restriction)
{
    switch (restriction) {
    case Restriction::Prohibited: return QStringLiteral("PROHIBITED");
    case Restriction::ReqAuthorisation: return QStringLiteral("REQ_AUTHORISATION");
    case Restriction::Conditional: return QStringLiteral("CONDITIONAL");
    case Restriction::NoRestriction: return QStringLiteral("NO_RESTRICTION");
    }
    return {};
}

QString restrictionWords(Restriction restriction)
{
    switch (restriction) {
    case Restriction::Prohibited: return QCoreApplication::translate("GeoZone", "Prohibited");
    case Restriction::ReqAuthorisation: return QCoreApplication::translate("GeoZone", "Authorisation needed");
    case Restriction::Conditional: return QCoreApplication::translate("GeoZone", "Conditions apply");
    case Restriction::NoRestriction: return QCoreApplication::translate("GeoZone", "Information only");
    }
    return {};
}

std::optional<Restriction> restrictionFromName(const QString &name)
{
    if (name == QLatin1String("PROHIBITED"))
        return Restriction::Prohibited;
    if (name == QLatin1String("REQ_AUTHORISATION") || name == QLatin1String("REQ_AUTHORIZATION"))
        return Restriction::ReqAuthorisation;
    if (name == QLatin1String("CONDITIONAL"))
        return Restriction::Conditional;
    if (name == QLatin1String("NO_RESTRICTION"))
        return Restriction::NoRestriction;
    return std::nullopt;
}

QString formatName(Format format)
{
    return format == Format::Ed269 ? QStringLiteral("ED-269") : QStringLiteral("ED-318");
}

bool appliesDuring(const std::vector<TimePeriod> &periods, const TimeWindow &window)
{
    if (periods.empty())
        return true;
    const qint64 from = window.from.toMSecsSinceEpoch(), to = std::max(from, window.to.toMSecsSinceEpoch());
    return std::any_of(periods.begin(), periods.end(), [&](const TimePeriod &p) { return periodApplies(p, from, to); });
}

QString applicabilityText(const std::vector<TimePeriod> &periods, const QTimeZone &zone)
{
    if (periods.empty() || std::any_of(periods.begin(), periods.end(), [](const TimePeriod &p) { return p.permanent; }))
        return QCoreApplication::translate("GeoZone", "always");
    const auto local = [&](const QDateTime &t) { return zone.isValid() ? t.toTimeZone(zone) : t.toLocalTime(); };
    QStringList out;
    for (const TimePeriod &p : periods) {
        QStringList parts;
        const QString format = QStringLiteral("yyyy-MM-dd HH:mm");
        if (p.start && p.end)
            parts << QCoreApplication::translate("GeoZone", "%1 to %2").arg(local(*p.start).toString(format), local(*p.end).toString(format));
        else if (p.start)
            parts << QCoreApplication::translate("GeoZone", "from %1").arg(local(*p.start).toString(format));
        else if (p.end)
            parts << QCoreApplication::translate("GeoZone", "until %1").arg(local(*p.end).toString(format));
        // The schedule in the zone's offset on the period's first day (or today's).
        const QDateTime at = p.start ? *p.start : QDateTime::currentDateTimeUtc();
        const int offset = local(at).offsetFromUtc();
        for (const DailyPeriod &d : p.schedule) {
            const int start = d.start + offset;
            const int shift = int(floorDiv(start, kDaySeconds));
            parts << QStringLiteral("%1 %2–%3").arg(dayNames(rotated(d.days, shift)), clock(start), clock(d.end + offset));
        }
        if (parts.isEmpty())
            parts << QCoreApplication::translate("GeoZone", "always");
        out << parts.join(QStringLiteral(", "));
    }
    return out.join(QStringLiteral("; "));
}

QString contactText(const Authority &a)
{
    QStringList parts;
    if (!a.name.isEmpty())
        parts << (a.service.isEmpty() ? a.name : QStringLiteral("%1 (%2)").arg(a.name, a.service));
    else if (!a.service.isEmpty())
        parts << a.service;
    for (const QString *s : {&a.contactName, &a.email, &a.phone, &a.siteUrl})
        if (!s->isEmpty())
            parts << *s;
    if (!a.intervalBefore.isEmpty())
        parts << QCoreApplication::translate("GeoZone", "ask %1 before").arg(a.intervalBefore);
    return parts.join(QStringLiteral(", "));
}

} // namespace sortie::airspace::ed
