#include "RouteEditor.h"

#include "ActionVariants.h"
#include "EditSegmentsCommand.h"
#include "InsertSegmentsCommand.h"
#include "MissionLog.h"
#include "MoveWaypointCommand.h"
#include "RemoveSegmentsCommand.h"
#include "ReorderSegmentsCommand.h"
#include "ReplaceRouteCommand.h"
#include "RouteModel.h"
#include "ScanVariants.h"
#include "SetRouteSettingsCommand.h"

#include <QUndoStack>

#include <algorithm>

namespace sortie::mission {

RouteEditor::RouteEditor(RouteModel *model, QUndoStack *stack, QObject *parent)
    : QObject(parent), m_model(model), m_stack(stack)
{
    m_model->setUndoStack(stack);
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

Waypoint RouteEditor::newWaypointAt(int row, const GeoPoint &position) const
{
    Waypoint w;
    const RouteSettings &rs = m_model->settings();
    w.altitude = std::max(rs.safeAltitude, std::min(50.0, rs.maxAltitude));
    w.speed = rs.initialSpeed;
    for (int r = std::min(row, m_model->count()) - 1; r >= 0; --r) {
        if (const Waypoint *prev = asWaypoint(m_model->segment(r)); prev && prev->role == WaypointRole::Pass) {
            w.altitude = prev->altitude;
            w.altitudeType = prev->altitudeType;
            w.speed = prev->speed;
            w.turnType = prev->turnType;
            break;
        }
    }
    w.position = position;
    return w;
}

int RouteEditor::addWaypoint(double latitude, double longitude)
{
    return insertWaypoint(m_model->count(), latitude, longitude);
}

int RouteEditor::insertWaypoint(int row, double latitude, double longitude)
{
    const GeoPoint p{latitude, longitude};
    if (!p.isValid() || row < 0 || row > m_model->count())
        return -1;
    return insertSegments(row, {newWaypointAt(row, p)}, QStringLiteral("Add waypoint %1").arg(row + 1));
}

int RouteEditor::insertSegments(int row, std::vector<Segment> segments, const QString &text)
{
    m_stack->push(new InsertSegmentsCommand(m_model, row, std::move(segments), text));
    return row;
}

void RouteEditor::moveWaypoint(int row, double latitude, double longitude)
{
    const GeoPoint p{latitude, longitude};
    if (row < 0 || row >= m_model->count() || !isWaypoint(m_model->segment(row)) || !p.isValid())
        return;
    m_stack->push(new MoveWaypointCommand(m_model, row, p, m_gesture));
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

void RouteEditor::editSegments(const QList<int> &rows, const std::function<void(Segment &)> &edit, const QString &text)
{
    std::vector<int> valid = validRows(rows);
    if (valid.empty())
        return;
    auto *cmd = new EditSegmentsCommand(m_model, std::move(valid), edit, text);
    if (cmd->isNoOp()) {
        delete cmd;
        return;
    }
    m_stack->push(cmd);
}

void RouteEditor::setAltitude(const QList<int> &rows, double altitude)
{
    editSegments(rows, [altitude](Segment &s) {
        if (Waypoint *w = asWaypoint(s)) {
            w->altitude = altitude;
        } else {
            auto &p = std::get<AreaScan>(s).parameters;
            p.heightMode = ScanHeightMode::Altitude;
            p.altitude = altitude;
            syncDerivedFields(p);
        }
    }, QStringLiteral("Set altitude to %1 m").arg(altitude));
}

bool RouteEditor::setAltitudeType(const QList<int> &rows, const QString &type, bool keepHeight)
{
    AltitudeType t;
    if (!parseAltitudeType(type, &t))
        return false;
    // Through the ground under each waypoint when it is known; otherwise the number stays (a
    // conversion would be a guess). A scan's altitude has no one point to convert at. See docs/missions.md.
    const GroundLookup ground = keepHeight ? m_ground : GroundLookup();
    editSegments(rows, [t, &ground](Segment &s) {
        if (Waypoint *w = asWaypoint(s)) {
            if (ground && w->altitudeType != t)
                if (const std::optional<double> g = ground(w->position))
                    w->altitude += t == AltitudeType::Amsl ? *g : -*g;
            w->altitudeType = t;
        } else {
            std::get<AreaScan>(s).parameters.altitudeType = t;
        }
    }, QStringLiteral("Set altitude type to %1").arg(altitudeTypeName(t)));
    return true;
}

void RouteEditor::setSpeed(const QList<int> &rows, double speed)
{
    editSegments(rows, [speed](Segment &s) {
        if (Waypoint *w = asWaypoint(s)) w->speed = speed;
        else std::get<AreaScan>(s).parameters.speed = speed;
    }, QStringLiteral("Set speed to %1 m/s").arg(speed));
}

bool RouteEditor::setTurnType(const QList<int> &rows, const QString &type)
{
    TurnType t;
    if (!parseTurnType(type, &t))
        return false;
    editSegments(rows, [t](Segment &s) { if (Waypoint *w = asWaypoint(s)) w->turnType = t; },
                 QStringLiteral("Set turn type to %1").arg(turnTypeName(t)));
    return true;
}

void RouteEditor::setAcceptanceRadius(const QList<int> &rows, double meters)
{
    editSegments(rows, [meters](Segment &s) { if (Waypoint *w = asWaypoint(s)) w->acceptanceRadius = meters; },
                 QStringLiteral("Set acceptance radius to %1 m").arg(meters));
}

bool RouteEditor::addAction(const QList<int> &rows, const QVariantMap &action)
{
    const auto a = actionFromVariant(action);
    if (!a) {
        qCWarning(lcMission) << "unknown action kind" << action.value(QStringLiteral("kind"));
        return false;
    }
    editSegments(rows, [&a](Segment &s) { if (Waypoint *w = asWaypoint(s)) w->actions.push_back(*a); },
                 QStringLiteral("Add action: %1").arg(describeAction(*a)));
    return true;
}

void RouteEditor::removeAction(const QList<int> &rows, int actionIndex)
{
    editSegments(rows, [actionIndex](Segment &s) {
        if (Waypoint *w = asWaypoint(s); w && actionIndex >= 0 && actionIndex < int(w->actions.size()))
            w->actions.erase(w->actions.begin() + actionIndex);
    }, QStringLiteral("Remove action"));
}

bool RouteEditor::setAction(const QList<int> &rows, int actionIndex, const QVariantMap &action)
{
    const auto a = actionFromVariant(action);
    if (!a)
        return false;
    editSegments(rows, [&a, actionIndex](Segment &s) {
        if (Waypoint *w = asWaypoint(s); w && actionIndex >= 0 && actionIndex < int(w->actions.size()))
            w->actions[size_t(actionIndex)] = *a;
    }, QStringLiteral("Edit action: %1").arg(describeAction(*a)));
    return true;
}

bool RouteEditor::setScanProperties(int row, const QVariantMap &parameters)
{
    if (row < 0 || row >= m_model->count() || !isAreaScan(m_model->segment(row)))
        return false;
    AreaScanParameters p = std::get<AreaScan>(m_model->segment(row)).parameters;
    if (!applyScanVariant(p, parameters))
        return false;
    setScanParameters(row, p);
    return true;
}

void RouteEditor::clearActions(const QList<int> &rows)
{
    editSegments(rows, [](Segment &s) { if (Waypoint *w = asWaypoint(s)) w->actions.clear(); },
                 QStringLiteral("Clear actions"));
}

int RouteEditor::addAreaScan(const QVariantList &polygon)
{
    AreaScan scan;
    for (const QVariant &v : polygon) {
        const QVariantMap m = v.toMap();
        const GeoPoint g{m.value(QStringLiteral("latitude")).toDouble(), m.value(QStringLiteral("longitude")).toDouble()};
        if (!g.isValid())
            return -1;
        scan.polygon.push_back(g);
    }
    if (scan.polygon.size() < 3)
        return -1;
    scan.parameters.altitude = std::max(m_model->settings().safeAltitude, std::min(60.0, m_model->settings().maxAltitude));
    scan.parameters.speed = m_model->settings().initialSpeed;
    syncDerivedFields(scan.parameters);
    return insertSegments(m_model->count(), {std::move(scan)}, QStringLiteral("Add area scan"));
}

void RouteEditor::setScanParameters(int row, const AreaScanParameters &parameters)
{
    AreaScanParameters synced = parameters;
    syncDerivedFields(synced);
    editSegments({row}, [&synced](Segment &s) { if (AreaScan *a = asAreaScan(s)) a->parameters = synced; },
                 QStringLiteral("Edit area scan %1").arg(row + 1));
}

void RouteEditor::setScanPolygon(int row, std::vector<GeoPoint> polygon)
{
    editSegments({row}, [&polygon](Segment &s) { if (AreaScan *a = asAreaScan(s)) a->polygon = polygon; },
                 QStringLiteral("Edit area scan %1 polygon").arg(row + 1));
}

bool RouteEditor::setRouteProperty(const QString &name, const QVariant &value)
{
    RouteSettings s = m_model->settings();
    bool ok = true;
    if (name == QLatin1String("name"))
        s.name = value.toString();
    else if (name == QLatin1String("safeAltitude"))
        s.safeAltitude = value.toDouble(&ok);
    else if (name == QLatin1String("maxAltitude"))
        s.maxAltitude = value.toDouble(&ok);
    else if (name == QLatin1String("initialSpeed"))
        s.initialSpeed = value.toDouble(&ok);
    else if (name == QLatin1String("maxSpeed"))
        s.maxSpeed = value.toDouble(&ok);
    else if (name == QLatin1String("cornerRadius"))
        s.cornerRadius = value.toDouble(&ok);
    else if (name == QLatin1String("takeoffHeight"))
        s.takeoffHeight = value.toDouble(&ok);
    else if (name == QLatin1String("maxHorizontalSpeed"))
        s.profile.maxHorizontalSpeed = value.toDouble(&ok);
    else
        return false;
    if (!ok)
        return false;
    if (!(s == m_model->settings()))
        setSettings(s, QStringLiteral("Set route %1").arg(name));
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
