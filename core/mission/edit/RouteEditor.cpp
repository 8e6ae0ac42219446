#include "RouteEditor.h"

#include "ActionVariants.h"
#include "DrawingTools.h"
#include "EditSegmentsCommand.h"
#include "EnclosedArea.h"
#include "FigurePoints.h"
#include "InsertSegmentsCommand.h"
#include "MissionLog.h"
#include "NewSegmentDefaults.h"
#include "RemoveSegmentsCommand.h"
#include "ReorderSegmentsCommand.h"
#include "ReplaceRouteCommand.h"
#include "RouteSettingNames.h"
#include "RouteModel.h"
#include "SegmentParameters.h"
#include "SetNfzChecksCommand.h"
#include "SetRouteSettingsCommand.h"

#include <QTimeZone>
#include <QLocale>
#include <QUndoStack>

#include <map>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace sortie::mission {

namespace {
GeoPoint geo(const QGeoCoordinate &c)
{
    return c.isValid() ? GeoPoint{c.latitude(), c.longitude()} : GeoPoint{std::nan(""), std::nan("")};
}

} // namespace

RouteEditor::RouteEditor(RouteModel *model, QUndoStack *stack, QObject *parent)
    : QObject(parent), m_model(model), m_stack(stack)
{
}

bool RouteEditor::refuse(const QString &reason)
{
    qCDebug(lcMission) << "edit refused:" << reason;
    emit refused(reason);
    return false;
}

std::vector<int> RouteEditor::validRows(const QList<int> &rows) const
{
    std::vector<int> out;
    out.reserve(size_t(rows.size()));
    for (int r : rows)
        if (r >= 0 && r < m_model->count())
            out.push_back(r);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

bool RouteEditor::edit(const QList<int> &rows, const std::function<bool(int, Segment &)> &change, const QString &text,
                       const QString &kind, EditStep step)
{
    const std::vector<int> valid = validRows(rows);
    if (valid.empty())
        return refuse(tr("Nothing is selected."));
    std::vector<int> changed;
    std::vector<Segment> before, after;
    for (int r : valid) {
        Segment s = m_model->segment(r);
        if (!change(r, s))
            return false;
        if (s == m_model->segment(r))
            continue;
        changed.push_back(r);
        before.push_back(m_model->segment(r));
        after.push_back(std::move(s));
    }
    // Continuing steps carry the gesture; so does the Done step that ends an open gesture.
    const int merge = (step == EditStep::Continuing || m_gestureOpen) ? m_gesture : 0;
    if (step == EditStep::Done) {
        ++m_gesture;
        m_gestureOpen = false;
    } else {
        m_gestureOpen = true;
    }
    if (!changed.empty())
        m_stack->push(new EditSegmentsCommand(m_model, std::move(changed), std::move(before), std::move(after), text, kind, merge));
    return true;
}

Waypoint RouteEditor::newWaypointAt(int row, const GeoPoint &position) const
{
    const Waypoint *previousPass = nullptr;
    for (int r = std::min(row, m_model->count()) - 1; r >= 0 && !previousPass; --r)
        if (const Waypoint *prev = asWaypoint(m_model->segment(r)); prev && prev->role == WaypointRole::Pass)
            previousPass = prev;
    return newWaypoint(m_model->settings(), previousPass, position);
}

int RouteEditor::addWaypoint(const QGeoCoordinate &at)
{
    return insertWaypoint(m_model->count(), at);
}

int RouteEditor::insertWaypoint(int row, const QGeoCoordinate &at)
{
    const GeoPoint p = geo(at);
    if (!p.isValid())
        return refuse(tr("That is not a valid position.")), -1;
    if (row < 0 || row > m_model->count())
        return refuse(tr("There is no row %1 to insert at.").arg(row + 1)), -1;
    return insertSegments(row, {newWaypointAt(row, p)}, tr("Add waypoint %1").arg(row + 1));
}

int RouteEditor::insertSegments(int row, std::vector<Segment> segments, const QString &text)
{
    const int count = int(segments.size());
    m_stack->push(new InsertSegmentsCommand(m_model, row, std::move(segments), text));
    emit rowsAdded(row, count);
    return row;
}

bool RouteEditor::moveWaypoints(const QList<int> &rows, const QList<QGeoCoordinate> &to, EditStep step)
{
    if (rows.size() != to.size() || rows.isEmpty())
        return refuse(tr("A move needs one position per waypoint."));
    std::unordered_map<int, GeoPoint> target;
    target.reserve(size_t(rows.size()));
    for (qsizetype i = 0; i < rows.size(); ++i) {
        const GeoPoint p = geo(to[i]);
        if (!p.isValid())
            return refuse(tr("That is not a valid position."));
        if (rows[i] < 0 || rows[i] >= m_model->count())
            return refuse(tr("There is no row %1.").arg(rows[i] + 1));
        target[rows[i]] = p;
    }
    const QString text = rows.size() == 1 ? tr("Move %1").arg(segmentLabel(rows.first(), m_model->segment(rows.first())))
                                          : tr("Move %n segment(s)", nullptr, int(rows.size()));
    return edit(rows, [&](int row, Segment &s) {
        moveSegmentTo(s, target.at(row));  // a figure moves whole, by its anchor (its marker on the map)
        return true;
    }, text, QStringLiteral("move"), step);
}

bool RouteEditor::setLatitude(int row, double latitude)
{
    if (row < 0 || row >= m_model->count() || !isWaypoint(m_model->segment(row)))
        return refuse(tr("Row %1 is not a waypoint.").arg(row + 1));
    const GeoPoint p = std::get<Waypoint>(m_model->segment(row)).position;
    return moveWaypoints({row}, {QGeoCoordinate(latitude, p.longitude)});
}

bool RouteEditor::setLongitude(int row, double longitude)
{
    if (row < 0 || row >= m_model->count() || !isWaypoint(m_model->segment(row)))
        return refuse(tr("Row %1 is not a waypoint.").arg(row + 1));
    const GeoPoint p = std::get<Waypoint>(m_model->segment(row)).position;
    return moveWaypoints({row}, {QGeoCoordinate(p.latitude, longitude)});
}

QList<int> RouteEditor::rowsOf(const QItemSelectionModel *selection) const
{
    QList<int> rows;
    if (!selection || selection->model() != m_model)
        return rows;
    for (const QModelIndex &i : selection->selectedIndexes())
        rows << i.row();
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    return rows;
}

void RouteEditor::removeRows(const QList<int> &rows)
{
    std::vector<int> valid = validRows(rows);
    if (!valid.empty())
        m_stack->push(new RemoveSegmentsCommand(m_model, std::move(valid)));
}

void RouteEditor::moveRows(const QList<int> &rows, int destination)
{
    std::vector<int> valid = validRows(rows);
    if (valid.empty() || destination < 0 || destination > m_model->count())
        return;
    m_stack->push(ReorderSegmentsCommand::moveRows(m_model, std::move(valid), destination));
}

void RouteEditor::reverse(const QList<int> &rows)
{
    const std::vector<int> valid = validRows(rows);
    const int first = valid.empty() ? 0 : valid.front();
    const int last = valid.empty() ? m_model->count() - 1 : valid.back();
    if (last > first)
        m_stack->push(ReorderSegmentsCommand::reverse(m_model, first, last));
}

bool RouteEditor::setAltitude(const QList<int> &rows, double altitude, EditStep step)
{
    if (!std::isfinite(altitude))
        return refuse(tr("The altitude needs a number."));
    return edit(rows, [&](int, Segment &s) { return applyAltitude(s, altitude); },
                tr("Set altitude to %1 m").arg(altitude), QStringLiteral("altitude"), step);
}

bool RouteEditor::applyAltitude(Segment &s, double altitude)
{
    if (Waypoint *w = asWaypoint(s)) {
        w->altitude = altitude;
        return true;
    }
    if (AlgorithmSegment *a = asAlgorithmSegment(s); a && !parameterNames(s, catalog()).contains(QStringLiteral("height"))) {
        if (a->figure == FigureType::Point || a->figure == FigureType::Circle)  // the point carries it
            for (FigurePoint &p : a->points)
                p.altitude = altitude;
        return true;
    }
    QString error;
    return setParameterValue(s, QStringLiteral("height"), altitude, &error, catalog()) || refuse(error);
}

bool RouteEditor::setAltitudeType(const QList<int> &rows, AltitudeType type, bool keepHeight)
{
    // Through the ground under each waypoint when it is known; otherwise the number stays (a
    // conversion would be a guess). A scan's altitude has no one point to convert at. See docs/missions.md.
    const GroundLookup ground = keepHeight ? m_ground : GroundLookup();
    QString error;
    return edit(rows, [&](int, Segment &s) {
        if (Waypoint *w = asWaypoint(s)) {
            if (ground && w->altitudeType != type)
                if (const std::optional<double> g = ground(w->position))
                    w->altitude += type == AltitudeType::Amsl ? *g : -*g;
            w->altitudeType = type;
            return true;
        }
        if (AlgorithmSegment *a = asAlgorithmSegment(s); a && !parameterNames(s, catalog()).contains(QStringLiteral("altitudeType"))) {
            for (FigurePoint &p : a->points)
                p.altitudeType = type;
            return true;
        }
        return setParameterValue(s, QStringLiteral("altitudeType"), QVariant::fromValue(type), &error, catalog()) || refuse(error);
    }, tr("Set altitude type to %1").arg(altitudeTypeName(type)), QStringLiteral("altitudeType"), EditStep::Done);
}

bool RouteEditor::setAltitudeIn(const QList<int> &rows, double altitude, AltitudeType frame)
{
    if (!std::isfinite(altitude))
        return refuse(tr("The altitude needs a number."));
    const QString frameName = altitudeTypeName(frame);
    // Checked first, so that a refusal leaves every row as it was.
    std::map<int, double> values;  // row -> the altitude in the row's own type
    for (int row : validRows(rows)) {
        const Segment &s = m_model->segment(row);
        const AltitudeType own = altitudeTypeOf(s);
        if (own == frame) {
            values.emplace(row, altitude);
            continue;
        }
        const Waypoint *w = asWaypoint(s);
        if (!w)
            return refuse(tr("Row %1 keeps its height %2: set it as %2, or change its altitude type first.")
                              .arg(row + 1).arg(altitudeTypeName(own)));
        const std::optional<double> ground = m_ground ? m_ground(w->position) : std::nullopt;
        if (!ground)
            return refuse(tr("Waypoint %1 is planned %2 and there is no terrain data under it: a height %3 cannot be converted.")
                              .arg(row + 1).arg(altitudeTypeName(own), frameName));
        values.emplace(row, frame == AltitudeType::Amsl ? altitude - *ground : altitude + *ground);
    }
    QList<int> valid;
    for (const auto &v : values)
        valid << v.first;
    return edit(valid, [&](int row, Segment &s) { return applyAltitude(s, values.at(row)); }, tr("Set altitude to %1 m %2").arg(altitude).arg(frameName), QStringLiteral("altitude"), EditStep::Done);
}

bool RouteEditor::setSpeed(const QList<int> &rows, double speed)
{
    return setParameter(rows, QStringLiteral("speed"), speed);
}

bool RouteEditor::setTurnType(const QList<int> &rows, TurnType type)
{
    return edit(rows, [type](int, Segment &s) {
        if (Waypoint *w = asWaypoint(s))
            w->turnType = type;
        return true;
    }, tr("Set turn type to %1").arg(turnTypeName(type)), QStringLiteral("turnType"), EditStep::Done);
}

bool RouteEditor::setAcceptanceRadius(const QList<int> &rows, double meters)
{
    return setParameter(rows, QStringLiteral("acceptanceRadius"), meters);
}

bool RouteEditor::setParameter(const QList<int> &rows, const QString &name, const QVariant &value, EditStep step)
{
    // Rows without the parameter are left alone; a bad value for one that has it cancels the edit.
    QString error;
    bool any = false;
    for (int r : validRows(rows))
        any |= parameterNames(m_model->segment(r), catalog()).contains(name);
    if (!any)
        return refuse(tr("No selected segment has a parameter \"%1\".").arg(name));
    return edit(rows, [&](int, Segment &s) {
        if (!parameterNames(s, catalog()).contains(name))
            return true;
        return setParameterValue(s, name, value, &error, catalog()) || refuse(error);
    }, tr("Set %1 to %2").arg(name, value.toString()), QStringLiteral("parameter:") + name, step);
}

bool RouteEditor::addAction(const QList<int> &rows, const QVariantMap &action)
{
    const auto a = actionFromVariant(action);
    if (!a)
        return refuse(tr("There is no action \"%1\".").arg(action.value(QStringLiteral("kind")).toString()));
    return edit(rows, [&a](int, Segment &s) {
        if (Waypoint *w = asWaypoint(s))
            w->actions.push_back(*a);
        return true;
    }, tr("Add action: %1").arg(describeAction(*a)), QStringLiteral("addAction"), EditStep::Done);
}

void RouteEditor::removeAction(const QList<int> &rows, int actionIndex)
{
    edit(rows, [actionIndex](int, Segment &s) {
        if (Waypoint *w = asWaypoint(s); w && actionIndex >= 0 && actionIndex < int(w->actions.size()))
            w->actions.erase(w->actions.begin() + actionIndex);
        return true;
    }, tr("Remove action"), QStringLiteral("removeAction"), EditStep::Done);
}

bool RouteEditor::setAction(const QList<int> &rows, int actionIndex, const QVariantMap &action)
{
    const auto a = actionFromVariant(action);
    if (!a)
        return refuse(tr("There is no action \"%1\" with these values.").arg(action.value(QStringLiteral("kind")).toString()));
    return edit(rows, [&](int, Segment &s) {
        if (Waypoint *w = asWaypoint(s); w && actionIndex >= 0 && actionIndex < int(w->actions.size())) {
            // Over what is there: a server action keeps what the map does not name.
            WaypointAction &there = w->actions[size_t(actionIndex)];
            there = actionFromVariant(action, &there).value_or(*a);
        }
        return true;
    }, tr("Edit action: %1").arg(describeAction(*a)), QStringLiteral("setAction"), EditStep::Done);
}

void RouteEditor::clearActions(const QList<int> &rows)
{
    edit(rows, [](int, Segment &s) {
        if (Waypoint *w = asWaypoint(s))
            w->actions.clear();
        return true;
    }, tr("Clear actions"), QStringLiteral("clearActions"), EditStep::Done);
}

int RouteEditor::addAreaScan(const QList<QGeoCoordinate> &polygon)
{
    AreaScan scan;
    for (const QGeoCoordinate &c : polygon)
        scan.polygon.push_back(geo(c));
    if (!enclosesArea(scan.polygon))
        return refuse(tr("An area scan needs at least three corners that enclose an area.")), -1;
    applyAreaScanDefaults(scan, m_model->settings());
    return insertSegments(m_model->count(), {std::move(scan)}, tr("Add area scan"));
}

bool RouteEditor::moveVertex(int row, int vertex, const QGeoCoordinate &to, EditStep step)
{
    const GeoPoint p = geo(to);
    if (!p.isValid())
        return refuse(tr("That is not a valid position."));
    return edit({row}, [&](int, Segment &s) {
        FigurePoints f = figurePointsOf(s);
        if (vertex < 0 || vertex >= f.size())
            return refuse(tr("Segment %1 has no point %2.").arg(row + 1).arg(vertex + 1));
        f.set(vertex, p);
        return true;
    }, tr("Move point %1 of segment %2").arg(vertex + 1).arg(row + 1), QStringLiteral("vertex:%1").arg(vertex), step);
}

bool RouteEditor::insertVertex(int row, int vertex, const QGeoCoordinate &at)
{
    const GeoPoint p = geo(at);
    if (!p.isValid())
        return refuse(tr("That is not a valid position."));
    return edit({row}, [&](int, Segment &s) {
        FigurePoints f = figurePointsOf(s);
        if (!f.growable() || vertex < 0 || vertex > f.size())
            return refuse(tr("Segment %1 has no edge there.").arg(row + 1));
        f.insert(vertex, p);
        return true;
    }, tr("Add a point to segment %1").arg(row + 1), QStringLiteral("insertVertex"), EditStep::Done);
}

bool RouteEditor::removeVertex(int row, int vertex)
{
    return edit({row}, [&](int, Segment &s) {
        FigurePoints f = figurePointsOf(s);
        if (vertex < 0 || vertex >= f.size())
            return refuse(tr("Segment %1 has no point %2.").arg(row + 1).arg(vertex + 1));
        if (f.size() <= f.minimum())
            return refuse(tr("This figure keeps at least %n point(s).", nullptr, f.minimum()));
        f.erase(vertex);
        return true;
    }, tr("Remove point %1 of segment %2").arg(vertex + 1).arg(row + 1), QStringLiteral("removeVertex"), EditStep::Done);
}

bool RouteEditor::setRadius(int row, double meters, EditStep step)
{
    if (!(meters > 0) || !std::isfinite(meters))
        return refuse(tr("A radius is above 0 m."));
    return edit({row}, [&](int, Segment &s) {
        AlgorithmSegment *a = asAlgorithmSegment(s);
        if (!a || a->figure != FigureType::Circle)
            return refuse(tr("Segment %1 is no circle.").arg(row + 1));
        if (a->figureParameters.empty())
            a->figureParameters.push_back(meters);
        else
            a->figureParameters[0] = meters;
        return true;
    }, tr("Set the radius of segment %1 to %2 m").arg(row + 1).arg(meters), QStringLiteral("radius"), step);
}

QStringList RouteEditor::drawingToolNames() const
{
    QStringList names;
    for (const DrawingTool &t : drawingToolsOf(catalog()))
        names << t.name;
    return names;
}

DrawingTool RouteEditor::drawingTool(int index) const
{
    const std::vector<DrawingTool> tools = drawingToolsOf(catalog());
    return index >= 0 && size_t(index) < tools.size() ? tools[size_t(index)] : DrawingTool{};
}

void RouteEditor::setCatalog(const AlgorithmCatalog *catalog)
{
    m_catalog = catalog;
    emit catalogChanged();
}

const AlgorithmCatalog &RouteEditor::catalog() const
{
    return m_catalog ? *m_catalog : AlgorithmCatalog::builtIn();
}

int RouteEditor::addSegment(const QString &algorithm, const QList<QGeoCoordinate> &points)
{
    const AlgorithmKind kind = algorithmKindOf(algorithm);
    const QString className = algorithm.contains(QLatin1Char('.')) || kind == AlgorithmKind::Unknown ? algorithm
                                                                                                      : algorithmClassName(kind);
    if (kind == AlgorithmKind::AreaScan)
        return addAreaScan(points);
    if (kind == AlgorithmKind::Waypoint || kind == AlgorithmKind::TakeOff || kind == AlgorithmKind::Landing) {
        if (points.size() != 1 || !geo(points.first()).isValid())
            return refuse(tr("A point segment needs one valid position.")), -1;
        Waypoint w = newWaypointAt(m_model->count(), geo(points.first()));
        w.role = kind == AlgorithmKind::TakeOff ? WaypointRole::Takeoff : kind == AlgorithmKind::Landing ? WaypointRole::Land : WaypointRole::Pass;
        return insertSegments(m_model->count(), {std::move(w)}, tr("Add %1").arg(roleName(w.role)));
    }
    const AlgorithmDefinition *def = catalog().byClassName(className);
    if (!def)
        return refuse(tr("Sortie has no description of the algorithm %1.").arg(algorithm)), -1;
    AlgorithmSegment a;
    a.algorithm = def->className;
    a.figure = def->figure;
    for (const QGeoCoordinate &c : points)
        a.points.push_back({geo(c), 0.0, AltitudeType::Agl});
    std::vector<GeoPoint> corners = figureOf(Segment(a));
    for (const GeoPoint &g : corners)
        if (!g.isValid())
            return refuse(tr("That is not a valid position.")), -1;
    if (int(corners.size()) < def->minimumPoints || (def->figure == FigureType::Polygon && !enclosesArea(corners)))
        return refuse(tr("%1 needs at least %n point(s)%2.", nullptr, def->minimumPoints)
                          .arg(def->displayName, def->figure == FigureType::Polygon ? tr(" enclosing an area") : QString())), -1;
    applyToolDefaults(a, *def, m_model->settings());
    return insertSegments(m_model->count(), {std::move(a)}, tr("Add %1").arg(def->displayName));
}

bool RouteEditor::setRouteProperty(const QString &name, const QVariant &value)
{
    RouteSettings s = m_model->settings();
    switch (assignRouteSetting(s, name, value)) {
    case SettingAssignment::UnknownName: return refuse(tr("A route has no setting \"%1\".").arg(name));
    case SettingAssignment::NotANumber: return refuse(tr("%1 needs a number.").arg(name));
    case SettingAssignment::Set: break;
    }
    if (!(s == m_model->settings()))
        setSettings(s, tr("Set route %1").arg(name));
    return true;
}

void RouteEditor::setCheckAerodromeNfz(bool check)
{
    if (check != m_model->settings().checkAerodromeNfz)
        m_stack->push(new SetNfzChecksCommand(m_model, check, m_model->settings().checkCustomNfz));
}

void RouteEditor::setCheckCustomNfz(bool check)
{
    if (check != m_model->settings().checkCustomNfz)
        m_stack->push(new SetNfzChecksCommand(m_model, m_model->settings().checkAerodromeNfz, check));
}

void RouteEditor::setPlannedStart(const QDateTime &start)
{
    RouteSettings s = m_model->settings();
    s.plannedStart = start.isValid() ? std::optional<QDateTime>(start.toUTC()) : std::nullopt;
    if (s.plannedStart != m_model->settings().plannedStart)
        setSettings(s, s.plannedStart ? tr("Plan the start for %1").arg(QLocale().toString(start.toLocalTime(), QLocale::ShortFormat))
                                      : tr("Start now"));
}

bool RouteEditor::setPlannedStartText(const QString &localText)
{
    const QString text = localText.trimmed();
    if (text.isEmpty()) {
        setPlannedStart({});
        return true;
    }
    QDateTime local = QDateTime::fromString(text, QLatin1String(kPlannedStartFormat));
    if (!local.isValid())
        return refuse(tr("\"%1\" is no start time: type it as %2, e.g. %3.")
                          .arg(text, QLatin1String(kPlannedStartFormat), QDateTime::currentDateTime().toString(QLatin1String(kPlannedStartFormat))));
    local.setTimeZone(QTimeZone::systemTimeZone());
    setPlannedStart(local);
    return true;
}

bool RouteEditor::recordAuthorisation(const QString &identifier, const QString &reference)
{
    const QString id = identifier.trimmed();
    if (id.isEmpty())
        return refuse(tr("An authorisation needs the zone's identifier."));
    RouteSettings s = m_model->settings();
    const QString ref = reference.trimmed();
    if (ref.isEmpty())
        s.authorisations.erase(id);
    else
        s.authorisations[id] = ref;
    if (!(s == m_model->settings()))
        setSettings(s, ref.isEmpty() ? tr("Remove the authorisation for %1").arg(id) : tr("Record authorisation %1 for %2").arg(ref, id));
    return true;
}

void RouteEditor::setSettings(const RouteSettings &settings, const QString &text)
{
    m_stack->push(new SetRouteSettingsCommand(m_model, settings, text));
}

void RouteEditor::replaceRoute(Route route, const QString &text)
{
    m_stack->push(new ReplaceRouteCommand(m_model, std::move(route), text));
}

} // namespace sortie::mission
