#include "EdReading.h"

#include "Egm96Geoid.h"

#include <QRegularExpression>

#include <cmath>

// i18n: not text below (file diagnostics naming ED fields and JSON paths, English as the GeoJSON and KML zone readers' are)
namespace sortie::airspace::ed::reading {

namespace {
constexpr double kFoot = 0.3048;
constexpr double kNoLimit = 99999.0;  // both standards' "unlimited" (and "FL999"-like placeholders above it)
} // namespace

GeoidAccess::GeoidAccess(QString gridPath) : m_gridPath(std::move(gridPath)) {}
GeoidAccess::~GeoidAccess() = default;

double GeoidAccess::amsl(const JsonCursor &c, const GeoPoint &where, double ellipsoidal)
{
    if (!m_tried) {
        m_tried = true;
        m_geoid = datum::Egm96Geoid::open(m_gridPath.isEmpty() ? datum::Egm96Geoid::defaultGridPath() : m_gridPath, &m_error);
    }
    if (!m_geoid)
        c.fail(QStringLiteral("a WGS84 (ellipsoidal) limit needs the EGM96 geoid grid: %1").arg(m_error));
    const std::optional<double> h = m_geoid->amslFromEllipsoidal(where.latitude, where.longitude, ellipsoidal);
    if (!h)
        c.fail(QStringLiteral("the EGM96 grid has no geoid height at %1, %2").arg(where.latitude).arg(where.longitude));
    return *h;
}

JsonCursor single(const JsonCursor &c)
{
    if (!c.value().is_array())
        return c;
    if (c.arraySize() != 1)
        c.fail(QStringLiteral("expected one value, found a list of %1").arg(c.arraySize()));
    return c.at(size_t(0));
}

QString text(const JsonCursor &c)
{
    const Json &v = c.value();
    if (v.is_null())
        return {};
    if (v.is_string())
        return c.string();
    if (v.is_object())
        return c.find("text") && !c.at("text").isNull() ? c.at("text").string() : QString();
    if (v.is_array()) {
        QString first;
        for (size_t i = 0; i < c.arraySize(); ++i) {
            const JsonCursor item = c.at(i);
            const QString t = text(item);
            if (first.isEmpty())
                first = t;
            if (item.value().is_object() && item.find("lang") && item.at("lang").value().is_string()
                && item.at("lang").string().startsWith(QLatin1String("en"), Qt::CaseInsensitive) && !t.isEmpty())
                return t;
        }
        return first;
    }
    c.fail(QStringLiteral("expected a text, found %1").arg(QLatin1String(v.type_name())));
}

QString textOr(const JsonCursor &object, const char *key)
{
    const auto c = object.find(key);
    return c ? text(*c) : QString();
}

QStringList strings(const JsonCursor &object, const char *key)
{
    const auto c = object.find(key);
    if (!c || c->isNull())
        return {};
    if (c->value().is_string())
        return {c->string()};
    QStringList out;
    for (size_t i = 0; i < c->arraySize(); ++i)
        out << c->at(i).string();
    return out;
}

QDateTime dateTime(const JsonCursor &c)
{
    const QString s = single(c).string().trimmed();
    QDateTime t = QDateTime::fromString(s, Qt::ISODateWithMs);
    if (!t.isValid() || !s.contains(QLatin1Char('T')))
        c.fail(QStringLiteral("\"%1\" is not an ISO 8601 date and time").arg(s));
    if (t.timeSpec() == Qt::LocalTime)  // no offset written: the standards' times are UTC
        t = QDateTime(t.date(), t.time(), QTimeZone::utc());
    return t.toUTC();
}

int timeOfDay(const JsonCursor &c)
{
    static const QRegularExpression form(QStringLiteral("^(\\d{2}):(\\d{2})(?::(\\d{2})(?:\\.\\d+)?)?(Z|[+-]\\d{2}(?::?\\d{2})?)?$"));
    const QString s = single(c).string().trimmed();
    const QRegularExpressionMatch m = form.match(s);
    if (!m.hasMatch())
        c.fail(QStringLiteral("\"%1\" is not a time of day (HH:MM, HH:MM:SS, with Z or an offset)").arg(s));
    const int h = m.captured(1).toInt(), min = m.captured(2).toInt(), sec = m.captured(3).toInt();
    if (!(h < 24 && min < 60 && sec < 60) && !(h == 24 && min == 0 && sec == 0))
        c.fail(QStringLiteral("\"%1\" is not a time of day").arg(s));
    int offset = 0;
    const QString zone = m.captured(4);
    if (!zone.isEmpty() && zone != QLatin1String("Z")) {
        const QString digits = zone.mid(1).remove(QLatin1Char(':'));
        const int oh = digits.left(2).toInt(), om = digits.size() > 2 ? digits.mid(2).toInt() : 0;
        if (oh > 14 || om > 59)
            c.fail(QStringLiteral("\"%1\" has no valid offset from UTC").arg(s));
        offset = (zone.startsWith(QLatin1Char('-')) ? -1 : 1) * (oh * 3600 + om * 60);
    }
    return h * 3600 + min * 60 + sec - offset;
}

std::uint8_t days(const JsonCursor &list)
{
    static const char *const names[] = {"MON", "TUE", "WED", "THU", "FRI", "SAT", "SUN"};
    std::uint8_t mask = 0;
    const auto add = [&](const JsonCursor &c) {
        const QString d = c.string().trimmed().toUpper();
        if (d == QLatin1String("ANY")) {
            mask = 0x7f;
            return;
        }
        for (int i = 0; i < 7; ++i)
            if (d == QLatin1String(names[i])) {
                mask |= std::uint8_t(1u << i);
                return;
            }
        c.fail(QStringLiteral("\"%1\" is not a day (MON ... SUN, ANY)").arg(d));
    };
    if (list.value().is_string()) {
        add(list);
    } else {
        for (size_t i = 0; i < list.arraySize(); ++i)
            add(list.at(i));
    }
    if (!mask)
        list.fail(QStringLiteral("a schedule needs at least one day"));
    return mask;
}

DailyPeriod dailyPeriod(const JsonCursor &c)
{
    c.requireObject();
    DailyPeriod d;
    d.days = days(c.at("day"));
    const auto start = c.find("startTime"), end = c.find("endTime");
    // ED-318 may give a daylight event (sunrise, sunset) instead of a clock time: Sortie does not
    // compute those, and a zone it cannot place in time is left out rather than guessed.
    if ((!start || start->isNull()) && c.find("startEvent"))
        c.failAt("startEvent", QStringLiteral("schedules by sunrise or sunset (startEvent) are not supported"));
    if ((!end || end->isNull()) && c.find("endEvent"))
        c.failAt("endEvent", QStringLiteral("schedules by sunrise or sunset (endEvent) are not supported"));
    d.start = start && !start->isNull() ? timeOfDay(*start) : 0;
    d.end = end && !end->isNull() ? timeOfDay(*end) : 86400 + d.start;
    // An end at or before the start (in the file's own clock) runs past midnight.
    if (d.end <= d.start) {
        d.overnight = true;
    } else if (d.end - d.start > 86400) {
        d.end -= 86400;
        d.overnight = true;
    }
    return d;
}

TimePeriod period(const JsonCursor &c)
{
    c.requireObject();
    TimePeriod p;
    if (const auto permanent = c.find("permanent"); permanent && !permanent->isNull()) {
        const JsonCursor v = single(*permanent);
        if (v.value().is_boolean()) {
            p.permanent = v.boolean();
        } else {
            const QString s = v.string().trimmed().toUpper();
            if (s != QLatin1String("YES") && s != QLatin1String("NO"))
                v.fail(QStringLiteral("permanent is \"%1\", neither YES nor NO").arg(s));
            p.permanent = s == QLatin1String("YES");
        }
    }
    if (const auto start = c.find("startDateTime"); start && !start->isNull())
        p.start = dateTime(*start);
    if (const auto end = c.find("endDateTime"); end && !end->isNull())
        p.end = dateTime(*end);
    if (p.start && p.end && !(*p.end > *p.start))
        c.failAt("endDateTime", QStringLiteral("the period ends (%1) before it starts (%2)")
                                    .arg(p.end->toString(Qt::ISODate), p.start->toString(Qt::ISODate)));
    if (const auto schedule = c.find("schedule"); schedule && !schedule->isNull())
        for (size_t i = 0; i < schedule->arraySize(); ++i)
            p.schedule.push_back(dailyPeriod(schedule->at(i)));
    return p;
}

Authority authority(const JsonCursor &c)
{
    c.requireObject();
    Authority a;
    a.name = textOr(c, "name");
    a.service = textOr(c, "service");
    a.contactName = textOr(c, "contactName");
    a.siteUrl = textOr(c, "siteURL");
    a.email = textOr(c, "email");
    a.phone = textOr(c, "phone");
    a.purpose = textOr(c, "purpose");
    a.intervalBefore = textOr(c, "intervalBefore");
    return a;
}

std::optional<VerticalLimit> limit(const JsonCursor &value, const QString &uom, const JsonCursor &reference, bool upper,
                                   const GeoPoint &where, GeoidAccess &geoid)
{
    const JsonCursor v = single(value);
    if (v.isNull()) {
        if (upper)
            return std::nullopt;
        v.fail(QStringLiteral("a lower limit is needed"));
    }
    double metres = v.number();
    if (metres >= kNoLimit) {
        if (!upper)
            v.fail(QStringLiteral("the lower limit %1 is the \"no limit\" value").arg(metres));
        return std::nullopt;
    }
    const QString unit = uom.trimmed().toUpper();
    if (unit == QLatin1String("FT"))
        metres *= kFoot;
    else if (unit != QLatin1String("M"))
        v.fail(QStringLiteral("unit \"%1\" is neither M nor FT").arg(uom));
    const QString ref = single(reference).string().trimmed().toUpper();
    if (ref == QLatin1String("AGL")) {
        if (!upper && metres <= 0)
            return std::nullopt;  // the ground
        return VerticalLimit{metres, VerticalReference::Agl};
    }
    if (ref == QLatin1String("AMSL"))
        return VerticalLimit{metres, VerticalReference::Amsl};
    if (ref == QLatin1String("WGS84"))
        return VerticalLimit{geoid.amsl(reference, where, metres), VerticalReference::Amsl};
    reference.fail(QStringLiteral("vertical reference \"%1\" is not AGL, AMSL or WGS84").arg(ref));
}

void checkLimits(const JsonCursor &c, const Volume &v)
{
    if (v.lower && v.upper && v.lower->reference == v.upper->reference && !(v.upper->metres > v.lower->metres))
        c.fail(QStringLiteral("the upper limit (%1 m) is not above the lower limit (%2 m)").arg(v.upper->metres).arg(v.lower->metres));
    if (!v.lower && v.upper && v.upper->reference == VerticalReference::Agl && !(v.upper->metres > 0))
        c.fail(QStringLiteral("the upper limit (%1 m AGL) is not above the ground").arg(v.upper->metres));
}

GeoPoint position(const JsonCursor &c)
{
    const size_t n = c.arraySize();
    if (n < 2 || n > 3)
        c.fail(QStringLiteral("a position is [longitude, latitude] or [longitude, latitude, altitude]"));
    const GeoPoint p{c.at(size_t(1)).number(), c.at(size_t(0)).number()};
    if (!p.isValid())
        c.fail(QStringLiteral("longitude or latitude out of range"));
    return p;
}

Polygon polygon(const JsonCursor &rings)
{
    Polygon out;
    if (rings.arraySize() == 0)
        rings.fail(QStringLiteral("a polygon needs an outer ring"));
    for (size_t r = 0; r < rings.arraySize(); ++r) {
        const JsonCursor ring = rings.at(r);
        std::vector<GeoPoint> points;
        for (size_t i = 0; i < ring.arraySize(); ++i) {
            const GeoPoint p = position(ring.at(i));
            if (points.empty() || !(points.back() == p))  // published files repeat vertices
                points.push_back(p);
        }
        while (points.size() > 1 && points.front() == points.back())
            points.pop_back();
        if (points.size() < 3)
            ring.fail(QStringLiteral("a ring needs at least 3 distinct positions, found %1").arg(points.size()));
        out.rings.push_back(std::move(points));
    }
    return out;
}

GeoPoint anchor(const Volume &v)
{
    if (v.circle)
        return v.circle->center;
    return v.polygons.empty() || v.polygons.front().rings.empty() ? GeoPoint{} : v.polygons.front().rings.front().front();
}

QString featureLabel(const Json &properties, size_t index)
{
    QString label = QStringLiteral("feature %1").arg(index + 1);
    if (!properties.is_object())
        return label;
    QStringList said;
    const auto name = properties.find("name");
    if (name != properties.end()) {
        const Json *n = &*name;
        if (n->is_array() && !n->empty())
            n = &(*n)[0];
        if (n->is_object() && n->contains("text"))
            n = &(*n)["text"];
        if (n->is_string())
            said << QStringLiteral("'%1'").arg(QString::fromStdString(n->get<std::string>()));
    }
    const auto id = properties.find("identifier");
    if (id != properties.end() && id->is_string())
        said << QString::fromStdString(id->get<std::string>());
    return said.isEmpty() ? label : QStringLiteral("%1 (%2)").arg(label, said.join(QStringLiteral(", ")));
}

QString leftOut(const QString &label, const mission::formats::JsonPathError &e)
{
    return QStringLiteral("%1 (at %2) was left out: %3").arg(label, QString::fromStdString(e.path), e.message);
}

} // namespace sortie::airspace::ed::reading
