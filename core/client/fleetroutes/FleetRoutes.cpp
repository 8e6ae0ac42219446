#include "FleetRoutes.h"
#include "LanguageChange.h"

#include "FlightPath.h"
#include "MissionProgress.h"
#include "MissionUploader.h"
#include "RouteAnalyzer.h"
#include "RouteDocument.h"
#include "RoutePreparation.h"
#include "RouteTiming.h"
#include "Vehicle.h"
#include "VehicleFleet.h"
#include "VehiclePalette.h"

#include <QLoggingCategory>

#include <algorithm>
#include <cmath>

Q_LOGGING_CATEGORY(lcFleetRoutes, "sortie.client.fleetroutes")

namespace sortie::client {

using vehicle::Vehicle;

namespace {

// Whole seconds for "did what is shown change", -1 for unknown.
qint64 shownSeconds(double seconds)
{
    return std::isfinite(seconds) ? qint64(std::floor(seconds)) : -1;
}

} // namespace

QString fleetRouteStateName(FleetRouteState state)
{
    switch (state) {
    case FleetRouteState::Planned: return QStringLiteral("planned");
    case FleetRouteState::Uploaded: return QStringLiteral("uploaded");
    case FleetRouteState::Flying: return QStringLiteral("flying");
    case FleetRouteState::Flown: return QStringLiteral("flown");
    }
    return {};
}

FleetRoutes::FleetRoutes(VehicleFleet *fleet, RouteDocument *document, RoutePreparation *preparation, QObject *parent)
    : QAbstractListModel(parent)
    , m_fleet(fleet)
    , m_document(document)
    , m_preparation(preparation)
{
    i18n::refreshOnLanguageChange(this); // states ("uploaded 14:02") are worded in data()
    Q_ASSERT(fleet);
    Q_ASSERT(!document == !preparation);
    // A vehicle that comes or goes moves the others' rows, so their colours.
    const auto fleetChanged = [this] {
        for (int row = int(m_rows.size()) - 1; row >= 0; --row) {
            if (!m_rows[size_t(row)].vehicle || fleetRow(m_rows[size_t(row)].vehicle) < 0)
                removeRow(row);
        }
        if (!m_rows.empty())
            emit dataChanged(index(0), index(count() - 1), {VehicleRowRole, ColorRole});
        refreshPlanned();
    };
    connect(fleet, &QAbstractItemModel::rowsInserted, this, fleetChanged);
    connect(fleet, &QAbstractItemModel::rowsRemoved, this, fleetChanged);
    connect(fleet, &QAbstractItemModel::modelReset, this, fleetChanged);
    if (preparation) {
        follow(preparation->uploader());
        connect(preparation, &RoutePreparation::vehicleIdChanged, this, &FleetRoutes::refreshPlanned);
        connect(document, &RouteDocument::loaded, this, &FleetRoutes::refreshPlanned);
        // Edits reach the planned row once they pause (the analyzer's coalesced recomputation).
        connect(document->analyzer(), &mission::RouteAnalyzer::recomputed, this, &FleetRoutes::refreshPlanned);
    }
}

FleetRoutes::~FleetRoutes() = default;

void FleetRoutes::follow(MissionUploader *uploader)
{
    connect(uploader, &MissionUploader::uploaded, this, [this, uploader](Vehicle *v) { uploaded(uploader, v); });
}

int FleetRoutes::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QHash<int, QByteArray> FleetRoutes::roleNames() const
{
    return {{VehicleIdRole, "vehicleId"}, {VehicleNameRole, "vehicleName"}, {VehicleRowRole, "vehicleRow"},
            {ColorRole, "color"}, {RouteNameRole, "routeName"}, {StateRole, "state"}, {StateTextRole, "stateText"},
            {FlightSecondsRole, "flightSeconds"}, {ElapsedSecondsRole, "elapsedSeconds"},
            {RemainingSecondsRole, "remainingSeconds"}, {UploadedAtRole, "uploadedAt"}, {PathRole, "path"}, {OpenRole, "open"}};
}

QVariant FleetRoutes::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= count())
        return {};
    const Row &row = m_rows[size_t(index.row())];
    const FleetRoute &r = row.value;
    const double nan = qQNaN();
    switch (role) {
    case VehicleIdRole: return r.vehicleId;
    case VehicleNameRole: return row.vehicle ? row.vehicle->name() : r.vehicleId;
    case VehicleRowRole: return fleetRow(row.vehicle);
    case ColorRole: return vehicleColor(fleetRow(row.vehicle));
    case RouteNameRole: return r.route.settings.name.isEmpty() ? tr("Unnamed route") : r.route.settings.name;
    case StateRole: return fleetRouteStateName(r.state);
    case StateTextRole: return row.stateText;
    case FlightSecondsRole: return r.flightSeconds;
    case ElapsedSecondsRole: return r.progress ? r.progress->elapsedSeconds : nan;
    case RemainingSecondsRole: return r.progress ? r.progress->remainingSeconds : nan;
    case UploadedAtRole: return r.uploadedAt;
    case PathRole: return QVariant::fromValue(row.path);
    case OpenRole: return isOpen(row);
    default: return {};
    }
}

std::vector<FleetRoute> FleetRoutes::routes() const
{
    std::vector<FleetRoute> all;
    all.reserve(m_rows.size());
    for (const Row &row : m_rows)
        all.push_back(row.value);
    return all;
}

std::vector<FleetRouteState> FleetRoutes::statesOf(const QString &vehicleId) const
{
    std::vector<FleetRouteState> states;
    for (const Row &row : m_rows)
        if (row.value.vehicleId == vehicleId)
            states.push_back(row.value.state);
    return states;
}

const FleetRoute *FleetRoutes::onBoard(const QString &vehicleId) const
{
    for (const Row &row : m_rows)
        if (row.value.vehicleId == vehicleId && !row.planned)
            return &row.value;
    return nullptr;
}

QPolygonF FleetRoutes::pathAt(int row) const
{
    return row >= 0 && row < count() ? m_rows[size_t(row)].path : QPolygonF();
}

int FleetRoutes::fleetRow(const Vehicle *v) const
{
    for (int row = 0; v && m_fleet && row < m_fleet->count(); ++row) {
        if (m_fleet->vehicleAt(row) == v)
            return row;
    }
    return -1;
}

int FleetRoutes::onBoardRow(const Vehicle *v) const
{
    for (size_t row = 0; row < m_rows.size(); ++row) {
        if (!m_rows[row].planned && m_rows[row].vehicle == v)
            return int(row);
    }
    return -1;
}

int FleetRoutes::plannedRow() const
{
    for (size_t row = 0; row < m_rows.size(); ++row) {
        if (m_rows[row].planned)
            return int(row);
    }
    return -1;
}

bool FleetRoutes::isOpen(const Row &row) const
{
    if (row.planned)
        return true;
    return m_preparation && row.value.vehicleId == m_preparation->vehicleId() && row.value.route == m_document->route();
}

void FleetRoutes::removeRow(int row)
{
    beginRemoveRows({}, row, row);
    m_rows.erase(m_rows.begin() + row);
    endRemoveRows();
    emit countChanged();
}

void FleetRoutes::describe(Row &row)
{
    std::vector<mission::PathPoint> points = mission::flightPath(row.value.route, &m_scans);
    row.path.clear();
    row.path.reserve(qsizetype(points.size()));
    for (const mission::PathPoint &p : points)
        row.path.append(QPointF(p.position.longitude, p.position.latitude));
    const auto timeline = mission::timePath(row.value.route, points, mission::timingOf(row.value.route.settings));
    row.value.flightSeconds = timeline ? timeline->totalSeconds() : qQNaN();
    if (!timeline)
        qCDebug(lcFleetRoutes).noquote() << row.value.route.settings.name << "has no flight time:" << timeline.error().toString();
    m_scans.retainRecentlyUsed();
}

void FleetRoutes::watch(Vehicle *v)
{
    std::erase_if(m_watched, [](const QPointer<Vehicle> &w) { return w.isNull(); }); // vehicles gone since
    if (std::find(m_watched.begin(), m_watched.end(), v) != m_watched.end())
        return;
    m_watched.emplace_back(v);
    // Every sample, not only new values: the elapsed time is the clock's, and runs on while a vehicle
    // hovers with the same values (track() tells whether the row changed).
    connect(v, &Vehicle::historyChanged, this, [this, v] { refreshVehicle(v); });
    connect(v, &Vehicle::identityChanged, this, [this, v] {
        for (size_t row = 0; row < m_rows.size(); ++row) {
            if (m_rows[row].vehicle == v)
                emit dataChanged(index(int(row)), index(int(row)), {VehicleNameRole});
        }
    });
    connect(v, &Vehicle::missionChanged, this, [this, v] { missionReplaced(v); });
}

void FleetRoutes::uploaded(MissionUploader *uploader, Vehicle *v)
{
    if (fleetRow(v) < 0)
        return; // not one of the fleet's vehicles
    Row fresh;
    fresh.value.vehicleId = v->fleetId();
    fresh.value.route = uploader->route();
    fresh.value.state = FleetRouteState::Uploaded;
    fresh.value.uploadedAt = QDateTime::currentDateTimeUtc();
    fresh.vehicle = v;
    fresh.held = v->mission();
    describe(fresh);
    track(fresh);
    watch(v);
    if (const int old = onBoardRow(v); old >= 0)
        removeRow(old);
    // On-board rows first, in the order of their uploads; the planned one last.
    const int at = plannedRow() >= 0 ? plannedRow() : count();
    beginInsertRows({}, at, at);
    m_rows.insert(m_rows.begin() + at, std::move(fresh));
    endInsertRows();
    emit countChanged();
    qCInfo(lcFleetRoutes).noquote() << "route" << m_rows[size_t(at)].value.route.settings.name << "on" << v->name();
    refreshPlanned();
}

void FleetRoutes::missionReplaced(Vehicle *v)
{
    const int row = onBoardRow(v);
    if (row >= 0 && v->mission() != m_rows[size_t(row)].held)
        removeRow(row); // it holds something this client did not send (or nothing)
}

void FleetRoutes::refreshVehicle(Vehicle *v)
{
    for (size_t row = 0; row < m_rows.size(); ++row) {
        if (m_rows[row].vehicle != v)
            continue;
        Row &r = m_rows[row];
        const bool changed = track(r);
        const QModelIndex at = index(int(row));
        if (changed)
            emit dataChanged(at, at, {StateRole, StateTextRole, ElapsedSecondsRole, RemainingSecondsRole});
    }
}

bool FleetRoutes::track(Row &row)
{
    Vehicle *v = row.vehicle;
    FleetRoute &r = row.value;
    if (v && !row.planned) {
        const QString mission = v->missionState();
        const bool active = mission == QLatin1String("active") || mission == QLatin1String("paused");
        const vehicle::MissionProgress progress
            = vehicle::MissionProgress::compute(v->mission(), v->missionCurrent(), v->position(), v->groundSpeed());
        const QDateTime now = QDateTime::currentDateTimeUtc();
        if (active) {
            if (r.state != FleetRouteState::Flying) {
                r.state = FleetRouteState::Flying;
                r.startedAt = now;
                r.stoppedShort.reset();
            }
            FleetRouteProgress p;
            p.count = int(v->mission().size());
            p.waypoint = std::clamp(v->missionCurrent() + 1, std::min(1, p.count), p.count); // 1 until it names one
            p.elapsedSeconds = double(r.startedAt.msecsTo(now)) / 1000.0;
            p.remainingSeconds = progress.timeLeft;
            r.progress = p;
        } else if (mission == QLatin1String("complete") && r.state == FleetRouteState::Flying) {
            r.state = FleetRouteState::Flown; // the progress keeps its last figures
            if (r.progress) {
                r.progress->waypoint = r.progress->count;
                r.progress->remainingSeconds = 0;
            }
        } else if (r.state == FleetRouteState::Flying) {
            r.state = FleetRouteState::Uploaded; // stopped short: still on board, no longer flown
            r.startedAt = {};
            r.stoppedShort = r.progress;
            r.progress.reset();
        }
    }
    const QString text = stateText(row);
    const qint64 elapsed = shownSeconds(r.progress ? r.progress->elapsedSeconds : qQNaN());
    const qint64 remaining = shownSeconds(r.progress ? r.progress->remainingSeconds : qQNaN());
    const bool changed = text != row.stateText || elapsed != row.elapsed || remaining != row.remaining;
    row.stateText = text;
    row.elapsed = elapsed;
    row.remaining = remaining;
    return changed;
}

QString FleetRoutes::stateText(const Row &row) const
{
    const FleetRoute &r = row.value;
    switch (r.state) {
    case FleetRouteState::Planned: return tr("planned");
    case FleetRouteState::Uploaded: return tr("uploaded %1").arg(r.uploadedAt.toLocalTime().toString(QStringLiteral("HH:mm")));
    case FleetRouteState::Flying:
        if (row.vehicle && row.vehicle->missionState() == QLatin1String("paused"))
            return tr("paused: waypoint %1 of %2").arg(r.progress->waypoint).arg(r.progress->count);
        return tr("flying: waypoint %1 of %2").arg(r.progress->waypoint).arg(r.progress->count);
    case FleetRouteState::Flown: return tr("flown");
    }
    return {};
}

void FleetRoutes::refreshPlanned()
{
    Vehicle *v = m_preparation && m_fleet && !m_preparation->vehicleId().isEmpty() ? m_fleet->vehicle(m_preparation->vehicleId()) : nullptr;
    bool wanted = v && !m_document->route().segments.empty();
    if (wanted) {
        const int board = onBoardRow(v);
        wanted = board < 0 || !(m_rows[size_t(board)].value.route == m_document->route());
    }
    int row = plannedRow();
    if (!wanted) {
        if (row >= 0)
            removeRow(row);
    } else if (row < 0 || m_rows[size_t(row)].vehicle != v || !(m_rows[size_t(row)].value.route == m_document->route())) {
        Row planned;
        planned.planned = true;
        planned.vehicle = v;
        planned.value.vehicleId = v->fleetId();
        planned.value.route = m_document->route();
        describe(planned);
        track(planned);
        watch(v);
        if (row < 0) {
            row = count();
            beginInsertRows({}, row, row);
            m_rows.push_back(std::move(planned));
            endInsertRows();
            emit countChanged();
        } else {
            m_rows[size_t(row)] = std::move(planned);
            emit dataChanged(index(row), index(row));
        }
    }
    // Which row is the open route may have changed with it.
    if (!m_rows.empty())
        emit dataChanged(index(0), index(count() - 1), {OpenRole});
}

} // namespace sortie::client
