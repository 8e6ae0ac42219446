// WPML action groups into Sortie's waypoint actions.
#include "WpmlReadActions.h"

#include "NumberText.h"

#include <algorithm>

namespace sortie::mission::formats::wpml {
namespace {

std::optional<double> paramNumber(const ReadAction &a, const char *key)
{
    const auto it = a.params.find(QString::fromLatin1(key));
    return it == a.params.end() ? std::nullopt : parseNumber(it->second.toLatin1());
}

bool isCamera(const QString &func)
{
    return func == QLatin1String("takePhoto") || func.endsWith(QLatin1String("Record")) || func.endsWith(QLatin1String("TimeLapse"));
}

// One action done on reaching a point; nullopt (with its notice) where Sortie has no equivalent.
Result<std::optional<WaypointAction>> actionOf(const ReadAction &a, const QString &where, int line, const QString &file,
                                               QStringList *notices)
{
    const auto fail = [&](const QString &why) { return MissionError{QStringLiteral("%1: %2").arg(where, why), file, line, 0, {}}; };
    if (a.func == QLatin1String("takePhoto"))
        return std::optional<WaypointAction>(CameraTriggerAction{TriggerState::SingleShot});
    if (a.func == QLatin1String("startRecord"))
        return std::optional<WaypointAction>(CameraTriggerAction{TriggerState::StartRecording});
    if (a.func == QLatin1String("stopRecord"))
        return std::optional<WaypointAction>(CameraTriggerAction{TriggerState::StopRecording});
    if (a.func == QLatin1String("startTimeLapse")) {
        // DJI's mapping capture: a photo every minShootInterval seconds until stopTimeLapse.
        const auto s = paramNumber(a, "minShootInterval");
        if (!s || !(*s > 0.0)) {
            *notices << QStringLiteral("%1: a startTimeLapse without a minShootInterval above 0 s is not kept").arg(where);
            return std::optional<WaypointAction>();
        }
        return std::optional<WaypointAction>(CameraSeriesByTimeAction{*s, 0, 0.0});
    }
    if (a.func == QLatin1String("stopTimeLapse"))
        return std::optional<WaypointAction>(CameraSeriesByDistanceAction{0.0, 0, 0.0});  // an interval of 0 stops a series
    if (a.func == QLatin1String("hover")) {
        const auto s = paramNumber(a, "hoverTime");
        if (!s)
            return fail(QStringLiteral("hover without a hoverTime"));
        return std::optional<WaypointAction>(WaitAction{*s, false});
    }
    if (a.func == QLatin1String("rotateYaw")) {
        const auto h = paramNumber(a, "aircraftHeading");
        if (!h)
            return fail(QStringLiteral("rotateYaw without an aircraftHeading"));
        return std::optional<WaypointAction>(HeadingAction{*h < 0.0 ? *h + 360.0 : *h, false});
    }
    if (a.func == QLatin1String("gimbalRotate")) {
        // Each angle counts where its enable flag is 1; WPML's pitch -90° is UgCS's tilt 90°.
        const auto enabled = [&a](const char *flag) { return paramNumber(a, flag).value_or(0) == 1; };
        CameraControlAction gimbal;
        if (enabled("gimbalPitchRotateEnable"))
            if (const auto pitch = paramNumber(a, "gimbalPitchRotateAngle"))
                gimbal.tiltDeg = -*pitch;
        if (enabled("gimbalRollRotateEnable"))
            gimbal.rollDeg = paramNumber(a, "gimbalRollRotateAngle");
        if (enabled("gimbalYawRotateEnable"))
            gimbal.yawDeg = paramNumber(a, "gimbalYawRotateAngle");
        if (gimbal == CameraControlAction{}) {
            *notices << QStringLiteral("%1: a gimbalRotate that turns nothing is not kept").arg(where);
            return std::optional<WaypointAction>();
        }
        return std::optional<WaypointAction>(gimbal);
    }
    *notices << QStringLiteral("%1: the WPML action \"%2\" has no Sortie equivalent and is not kept").arg(where, a.func);
    return std::optional<WaypointAction>();
}

} // namespace

QString waypointList(const std::vector<int> &numbers)
{
    std::vector<int> n = numbers;
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
    QStringList parts;
    for (size_t i = 0; i < n.size();) {
        size_t j = i;
        while (j + 1 < n.size() && n[j + 1] == n[j] + 1)
            ++j;
        parts << (j > i ? QStringLiteral("%1-%2").arg(n[i]).arg(n[j]) : QString::number(n[i]));
        i = j + 1;
    }
    return (n.size() == 1 ? QStringLiteral("waypoint ") : QStringLiteral("waypoints ")) + parts.join(QStringLiteral(", "));
}

Result<void> readActions(const ReadFolder &wayline, const std::vector<const ReadPoint *> &byIndex, Route &route,
                         const QString &prefix, const QString &file, QStringList *notices)
{
    const size_t n = byIndex.size();
    const auto at = [&](size_t i) { return QStringLiteral("%1, waypoint %2").arg(prefix).arg(i + 1); };
    for (size_t i = 0; i < n; ++i) {
        for (const ReadGroup &g : byIndex[i]->groups) {
            const size_t start = std::clamp<size_t>(size_t(std::max(g.start, 0)), 0, n - 1);
            const QString where = at(start);
            auto *w = asWaypoint(route.segments[start]);
            // Repeated triggers: a photo series from the group's first point, stopped at its last.
            if (g.trigger == QLatin1String("multipleDistance") || g.trigger == QLatin1String("multipleTiming")) {
                for (const ReadAction &a : g.actions) {
                    if (a.func != QLatin1String("takePhoto") || !g.interval || !(*g.interval > 0.0)) {
                        *notices << QStringLiteral("%1: a \"%2\" repeated by %3 is not kept").arg(where, a.func, g.trigger);
                        continue;
                    }
                    if (g.trigger == QLatin1String("multipleDistance"))
                        w->actions.push_back(CameraSeriesByDistanceAction{*g.interval, 0, 0.0});
                    else
                        w->actions.push_back(CameraSeriesByTimeAction{*g.interval, 0, 0.0});
                    const size_t last = std::clamp<size_t>(size_t(std::max(g.end, g.start)), 0, n - 1);
                    // Stopped at its last point, unless the route ends there or a camera action follows.
                    const bool cameraAtEnd = [&] {
                        for (const ReadGroup &other : byIndex[last]->groups)
                            if (&other != &g && other.start == int(last))
                                for (const ReadAction &oa : other.actions)
                                    if (isCamera(oa.func))
                                        return true;
                        return false;
                    }();
                    if (last + 1 < n && !cameraAtEnd)
                        asWaypoint(route.segments[last])->actions.push_back(CameraSeriesByDistanceAction{0.0, 0, 0.0});
                }
                continue;
            }
            const bool onReaching = g.trigger.isEmpty() || g.trigger == QLatin1String("reachPoint");
            for (const ReadAction &a : g.actions) {
                if (a.func == QLatin1String("gimbalEvenlyRotate")) {
                    *notices << QStringLiteral("%1: the gimbal pitched evenly (gimbalEvenlyRotate) over the leg that follows is not kept").arg(where);
                    continue;
                }
                Result<std::optional<WaypointAction>> action = actionOf(a, where, byIndex[i]->line, file, notices);
                if (!action)
                    return action.error();
                if (!action->has_value())
                    continue;  // told in actionOf
                if (!onReaching)
                    *notices << QStringLiteral("%1: \"%2\" triggered %3 is done on reaching the point").arg(where, a.func, g.trigger);
                w->actions.push_back(**action);
            }
        }
    }
    // The start actions run before the flight to the first waypoint; Sortie's route has no such
    // place, so they lead the first waypoint's actions (and go back as start actions on export).
    if (wayline.startGroup && n > 0) {
        std::vector<WaypointAction> start;
        QStringList kept;
        for (const ReadAction &a : wayline.startGroup->actions) {
            Result<std::optional<WaypointAction>> action = actionOf(a, prefix + QStringLiteral(", start actions"), byIndex[0]->line, file, notices);
            if (!action)
                return action.error();
            if (action->has_value()) {
                start.push_back(**action);
                kept << a.func;
            }
        }
        if (!start.empty()) {
            auto &first = asWaypoint(route.segments.front())->actions;
            first.insert(first.begin(), start.begin(), start.end());
            *notices << QStringLiteral("%1: the start actions (%2) run at waypoint 1 here, before its own actions; DJI runs them before the flight to it")
                            .arg(prefix, kept.join(QStringLiteral(", ")));
        }
    }
    return {};
}

} // namespace sortie::mission::formats::wpml
