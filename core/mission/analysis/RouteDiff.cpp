#include "RouteDiff.h"

#include "Geodesy.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace sortie::mission {

namespace {

using Kind = RouteChange::Kind;


// Up to two decimals, no trailing zeros: 80, 100.5, 0.25.
QString num(double v) { return QString::number(std::round(v * 100.0) / 100.0, 'g', 12); }

// Distances: whole metres from 10 m, one decimal below.
QString meters(double v) { return v >= 10 ? QString::number(std::lround(v)) : QString::number(std::round(v * 10) / 10, 'g', 3); }

QString label(const Segment &s, int row)
{
    if (isWaypoint(s))
        return RouteDiff::tr("WP %1").arg(row + 1);
    if (isAreaScan(s))
        return RouteDiff::tr("Scan %1").arg(row + 1);
    return RouteDiff::tr("%1 %2").arg(algorithmLabel(std::get<AlgorithmSegment>(s))).arg(row + 1);
}

QString quoted(const QString &s) { return s.isEmpty() ? RouteDiff::tr("(none)") : QStringLiteral("\"%1\"").arg(s); }

QString endActionName(EndAction a) { return a == EndAction::ReturnHome ? RouteDiff::tr("return home") : RouteDiff::tr("none"); }

// Cost of pairing two segments as "the same one, changed", against 1 for an addition and 1 for a
// removal: less than both together for anything of the same kind, closer ones cheaper.
double pairCost(const Segment &a, const Segment &b)
{
    if (a == b)
        return 0.0;
    if (a.index() != b.index())
        return 3.0;
    const double distance = geodesicDistance(anchorOf(a), anchorOf(b));
    return 0.3 + std::min(1.5, distance / 500.0);
}

} // namespace

RouteDiff RouteDiff::compare(const Route &before, const Route &after)
{
    RouteDiff diff;
    diff.compareSettings(before.settings, after.settings);
    diff.compareSegments(before.segments, after.segments);
    return diff;
}

QStringList RouteDiff::texts() const
{
    QStringList list;
    for (const RouteChange &c : m_changes)
        list.append(c.text);
    return list;
}

QString RouteDiff::summary(int listed) const
{
    if (m_changes.empty())
        return tr("No changes");
    QStringList first;
    for (int i = 0; i < count() && i < listed; ++i)
        first.append(m_changes[size_t(i)].text);
    QString text = (count() == 1 ? tr("1 change: ") : tr("%1 changes: ").arg(count())) + first.join(QStringLiteral(", "));
    if (count() > listed)
        text += tr(" and %1 more").arg(count() - listed);
    return text;
}

void RouteDiff::add(Kind kind, int row, QString text, double distance)
{
    m_changes.push_back({kind, row, distance, std::move(text)});
}

void RouteDiff::compareSettings(const RouteSettings &a, const RouteSettings &b)
{
    if (a.name != b.name)
        add(Kind::Settings, -1, tr("name %1 → %2").arg(quoted(a.name), quoted(b.name)));
    auto value = [this](double x, double y, const char *what, const char *unit) {
        if (x != y)
            add(Kind::Settings, -1, tr("%1 %2 → %3 %4").arg(tr(what), num(x), num(y), tr(unit)));
    };
    value(a.safeAltitude, b.safeAltitude, QT_TRANSLATE_NOOP("RouteDiff", "safe altitude"), QT_TRANSLATE_NOOP("RouteDiff", "m"));
    value(a.maxAltitude, b.maxAltitude, QT_TRANSLATE_NOOP("RouteDiff", "maximum altitude"), QT_TRANSLATE_NOOP("RouteDiff", "m"));
    value(a.initialSpeed, b.initialSpeed, QT_TRANSLATE_NOOP("RouteDiff", "initial speed"), QT_TRANSLATE_NOOP("RouteDiff", "m/s"));
    value(a.maxSpeed, b.maxSpeed, QT_TRANSLATE_NOOP("RouteDiff", "maximum speed"), QT_TRANSLATE_NOOP("RouteDiff", "m/s"));
    value(a.cornerRadius, b.cornerRadius, QT_TRANSLATE_NOOP("RouteDiff", "corner radius"), QT_TRANSLATE_NOOP("RouteDiff", "m"));
    value(a.takeoffHeight, b.takeoffHeight, QT_TRANSLATE_NOOP("RouteDiff", "takeoff height"), QT_TRANSLATE_NOOP("RouteDiff", "m"));
    if (a.profile != b.profile)
        add(Kind::Settings, -1, a.profile.name != b.profile.name
                                    ? tr("vehicle profile %1 → %2").arg(quoted(a.profile.name), quoted(b.profile.name))
                                    : tr("vehicle profile %1 changed").arg(quoted(b.profile.name)));
    if (a.failsafes != b.failsafes)
        add(Kind::Settings, -1, tr("failsafe actions changed"));
    if (a.home != b.home) {
        if (!a.home)
            add(Kind::Settings, -1, tr("home set"));
        else if (!b.home)
            add(Kind::Settings, -1, tr("home removed"));
        else if (a.home->position != b.home->position)
            add(Kind::Settings, -1, tr("home moved %1 m").arg(meters(geodesicDistance(a.home->position, b.home->position))));
        else
            add(Kind::Settings, -1, tr("home altitude %1 → %2 m").arg(num(a.home->altitudeAmsl), num(b.home->altitudeAmsl)));
    }
    if (a.endAction != b.endAction)
        add(Kind::Settings, -1, tr("end action %1 → %2").arg(endActionName(a.endAction), endActionName(b.endAction)));
    auto flag = [this](bool x, bool y, const char *what) {
        if (x != y)
            add(Kind::Settings, -1, tr("%1 %2").arg(tr(what), y ? tr("on") : tr("off")));
    };
    flag(a.checkAerodromeNfz, b.checkAerodromeNfz, QT_TRANSLATE_NOOP("RouteDiff", "aerodrome zone check"));
    flag(a.checkCustomNfz, b.checkCustomNfz, QT_TRANSLATE_NOOP("RouteDiff", "custom zone check"));
    if (a.plannedStart != b.plannedStart)
        add(Kind::Settings, -1, b.plannedStart ? tr("planned start %1").arg(b.plannedStart->toUTC().toString(Qt::ISODate))
                                               : tr("planned start removed: now"));
    for (const auto &[identifier, reference] : b.authorisations) {
        const auto before = a.authorisations.find(identifier);
        if (before == a.authorisations.end() || before->second != reference)
            add(Kind::Settings, -1, tr("authorisation for %1: %2").arg(identifier, reference));
    }
    for (const auto &[identifier, reference] : a.authorisations)
        if (!b.authorisations.count(identifier))
            add(Kind::Settings, -1, tr("authorisation for %1 removed").arg(identifier));
}

void RouteDiff::compareSegments(const std::vector<Segment> &a, const std::vector<Segment> &b)
{
    // The shared head and tail are unchanged; only the middle is aligned.
    size_t head = 0;
    while (head < a.size() && head < b.size() && a[head] == b[head])
        ++head;
    size_t tail = 0;
    while (tail < a.size() - head && tail < b.size() - head && a[a.size() - 1 - tail] == b[b.size() - 1 - tail])
        ++tail;
    const size_t n = a.size() - head - tail;
    const size_t m = b.size() - head - tail;

    enum class Op { Pair, Remove, Add };
    std::vector<Op> ops;
    constexpr size_t kMaxCells = 4'000'000; // beyond that (two huge rewrites), pair in order
    if (n * m <= kMaxCells) {
        // Edit distance: pairing costs pairCost, adding or removing costs 1.
        std::vector<float> cost((n + 1) * (m + 1));
        auto at = [&](size_t i, size_t j) -> float & { return cost[i * (m + 1) + j]; };
        for (size_t i = 0; i <= n; ++i)
            at(i, 0) = float(i);
        for (size_t j = 0; j <= m; ++j)
            at(0, j) = float(j);
        for (size_t i = 1; i <= n; ++i) {
            for (size_t j = 1; j <= m; ++j) {
                const float pair = at(i - 1, j - 1) + float(pairCost(a[head + i - 1], b[head + j - 1]));
                at(i, j) = std::min({pair, at(i - 1, j) + 1.0f, at(i, j - 1) + 1.0f});
            }
        }
        size_t i = n, j = m;
        while (i > 0 || j > 0) {
            if (i > 0 && j > 0 && at(i, j) == at(i - 1, j - 1) + float(pairCost(a[head + i - 1], b[head + j - 1]))) {
                ops.push_back(Op::Pair);
                --i, --j;
            } else if (j > 0 && at(i, j) == at(i, j - 1) + 1.0f) {
                ops.push_back(Op::Add); // backwards: a removal at the same place reads first
                --j;
            } else {
                ops.push_back(Op::Remove);
                --i;
            }
        }
        std::reverse(ops.begin(), ops.end());
    } else {
        ops.assign(std::min(n, m), Op::Pair);
        ops.insert(ops.end(), n > m ? n - m : 0, Op::Remove);
        ops.insert(ops.end(), m > n ? m - n : 0, Op::Add);
    }

    size_t i = head, j = head;
    for (Op op : ops) {
        switch (op) {
        case Op::Pair:
            compareSegment(a[i], b[j], int(j));
            ++i, ++j;
            break;
        case Op::Remove:
            add(Kind::Removed, int(i), tr("%1 removed").arg(label(a[i], int(i))));
            ++i;
            break;
        case Op::Add:
            add(Kind::Added, int(j), tr("%1 added").arg(label(b[j], int(j))));
            ++j;
            break;
        }
    }
}

void RouteDiff::compareSegment(const Segment &before, const Segment &after, int row)
{
    if (before == after)
        return;
    const QString name = label(after, row);
    const size_t listed = m_changes.size();
    compareFields(before, after, row, name);
    if (m_changes.size() == listed) // differs only in fields without a description of their own
        add(isWaypoint(after) ? Kind::Waypoint : Kind::AreaScan, row, tr("%1 changed").arg(name));
}

void RouteDiff::compareFields(const Segment &before, const Segment &after, int row, const QString &name)
{
    if (const Waypoint *a = asWaypoint(before), *b = asWaypoint(after); a && b) {
        if (a->position != b->position) {
            const double d = geodesicDistance(a->position, b->position);
            add(Kind::Moved, row, tr("%1 moved %2 m").arg(name, meters(d)), d);
        }
        if (a->altitudeType != b->altitudeType)
            add(Kind::Altitude, row, tr("altitude of %1 %2 m %3 → %4 m %5")
                                         .arg(name, num(a->altitude), altitudeTypeName(a->altitudeType), num(b->altitude),
                                              altitudeTypeName(b->altitudeType)));
        else if (a->altitude != b->altitude)
            add(Kind::Altitude, row, tr("altitude of %1 %2 → %3 m").arg(name, num(a->altitude), num(b->altitude)));
        if (a->speed != b->speed)
            add(Kind::Speed, row, tr("speed of %1 %2 → %3 m/s").arg(name, num(a->speed), num(b->speed)));
        if (a->actions != b->actions) {
            auto text = [](const std::vector<WaypointAction> &actions) {
                return actions.empty() ? tr("none") : describeActions(actions);
            };
            add(Kind::Actions, row, tr("actions of %1: %2 → %3").arg(name, text(a->actions), text(b->actions)));
        }
        if (a->turnType != b->turnType)
            add(Kind::Waypoint, row, tr("turn at %1 %2 → %3").arg(name, turnTypeName(a->turnType), turnTypeName(b->turnType)));
        if (a->acceptanceRadius != b->acceptanceRadius)
            add(Kind::Waypoint, row, tr("acceptance radius of %1 %2 → %3 m").arg(name, num(a->acceptanceRadius), num(b->acceptanceRadius)));
        if (a->role != b->role)
            add(Kind::Waypoint, row, tr("%1 %2 → %3").arg(name, roleName(a->role), roleName(b->role)));
        return;
    }
    if (const AlgorithmSegment *a = asAlgorithmSegment(before), *b = asAlgorithmSegment(after); a && b) {
        if (a->points != b->points || a->figureParameters != b->figureParameters)
            add(Kind::AreaScan, row, tr("figure of %1 reshaped").arg(name));
        for (const ParameterValue &v : b->parameters) {
            const QString *old = a->value(v.name);
            if (!old || *old != v.value)
                add(Kind::AreaScan, row, tr("%1 of %2 %3 → %4").arg(v.name, name, old ? quoted(*old) : tr("(none)"), quoted(v.value)));
        }
        for (const ParameterValue &v : a->parameters)
            if (!b->value(v.name))
                add(Kind::AreaScan, row, tr("%1 of %2 removed").arg(v.name, name));
        if (a->actions != b->actions)
            add(Kind::Actions, row, tr("actions of %1 changed").arg(name));
        return;
    }
    const AreaScan *a = asAreaScan(before);
    const AreaScan *b = asAreaScan(after);
    if (!a || !b)
        return;
    if (a->polygon != b->polygon)
        add(Kind::AreaScan, row, a->polygon.size() == b->polygon.size()
                                     ? tr("area of %1 reshaped").arg(name)
                                     : tr("area of %1 reshaped (%2 → %3 corners)").arg(name).arg(a->polygon.size()).arg(b->polygon.size()));
    const AreaScanParameters &p = a->parameters;
    const AreaScanParameters &q = b->parameters;
    auto value = [&](double x, double y, const char *what, const char *unit) {
        if (x != y)
            add(Kind::AreaScan, row, tr("%1 of %2 %3 → %4 %5").arg(tr(what), name, num(x), num(y), tr(unit)));
    };
    value(scanAltitude(p), scanAltitude(q), QT_TRANSLATE_NOOP("RouteDiff", "altitude"), QT_TRANSLATE_NOOP("RouteDiff", "m"));
    if (p.altitudeType != q.altitudeType)
        add(Kind::AreaScan, row, tr("altitude of %1 now %2").arg(name, altitudeTypeName(q.altitudeType)));
    if (p.heightMode != q.heightMode)
        add(Kind::AreaScan, row, q.heightMode == ScanHeightMode::GroundSampleDistance ? tr("%1 now flies by ground sample distance").arg(name)
                                                                                      : tr("%1 now flies by altitude").arg(name));
    value(p.frontOverlapPercent, q.frontOverlapPercent, QT_TRANSLATE_NOOP("RouteDiff", "front overlap"), "%");
    value(p.sideOverlapPercent, q.sideOverlapPercent, QT_TRANSLATE_NOOP("RouteDiff", "side overlap"), "%");
    value(p.directionDeg, q.directionDeg, QT_TRANSLATE_NOOP("RouteDiff", "direction"), "°");
    value(p.turnaroundMeters, q.turnaroundMeters, QT_TRANSLATE_NOOP("RouteDiff", "turnaround"), QT_TRANSLATE_NOOP("RouteDiff", "m"));
    value(p.speed, q.speed, QT_TRANSLATE_NOOP("RouteDiff", "speed"), QT_TRANSLATE_NOOP("RouteDiff", "m/s"));
    if (p.camera != q.camera)
        add(Kind::AreaScan, row, p.camera.name != q.camera.name ? tr("camera of %1 %2 → %3").arg(name, quoted(p.camera.name), quoted(q.camera.name))
                                                                : tr("camera of %1 changed").arg(name));
}

} // namespace sortie::mission
