#include "RouteModel.h"
#include "LanguageChange.h"

#include "ActionVariants.h"
#include "AreaScanPlanner.h"
#include "SegmentParameters.h"

#include <QTimeZone>

#include <algorithm>
#include <cmath>

namespace sortie::mission {

namespace {
// Beyond this many separate runs a removal or restore resets the model instead of signalling
// each run: one O(n) pass beats thousands of O(n) erases.
constexpr size_t kMaxRunsSignalled = 16;

QVariantMap parametersToVariant(const Segment &s)
{
    QVariantMap map;
    for (const QString &name : parameterNames(s))
        map.insert(name, parameterValue(s, name));
    return map;
}
}

std::vector<std::pair<int, int>> contiguousRuns(const std::vector<int> &rows)
{
    std::vector<std::pair<int, int>> runs;
    for (int r : rows) {
        if (!runs.empty() && runs.back().second + 1 == r)
            runs.back().second = r;
        else
            runs.emplace_back(r, r);
    }
    return runs;
}

RouteModel::RouteModel(QObject *parent) : QAbstractListModel(parent)
{
    i18n::refreshOnLanguageChange(this); // segment names and summaries are translated in data()
}

int RouteModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QHash<int, QByteArray> RouteModel::roleNames() const
{
    return {
        {KindRole, "kind"}, {SequenceRole, "sequence"}, {LatitudeRole, "latitude"}, {LongitudeRole, "longitude"},
        {AltitudeRole, "altitude"}, {AltitudeTypeRole, "altitudeType"}, {SpeedRole, "speed"}, {TurnTypeRole, "turnType"},
        {AcceptanceRadiusRole, "acceptanceRadius"}, {ActionCountRole, "actionCount"}, {ActionsSummaryRole, "actionsSummary"},
        {ActionsRole, "actions"}, {ActionMarksRole, "actionMarks"}, {PolygonRole, "polygon"}, {ScanParametersRole, "scanParameters"},
        {LabelRole, "label"},
        {Qt::DisplayRole, "display"},
    };
}

QVariant RouteModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Segment &s = segment(index.row());
    const Waypoint *w = asWaypoint(s);
    // A value a segment does not give (an unknown algorithm's altitude) is missing, never 0.
    auto known = [](double v) { return std::isnan(v) ? QVariant() : QVariant(v); };
    switch (role) {
    case Qt::DisplayRole:  // no row number in it: rows are renumbered by inserts, their text is not
        return QStringLiteral("%1 %2, %3 · %4 m %5").arg(segmentKindName(s))
            .arg(anchorOf(s).latitude, 0, 'f', 6).arg(anchorOf(s).longitude, 0, 'f', 6)
            .arg(altitudeOf(s)).arg(altitudeTypeName(altitudeTypeOf(s)));
    case KindRole: return segmentKindName(s);
    case LabelRole: return segmentLabel(index.row(), s);
    case SequenceRole: return index.row() + 1;
    case LatitudeRole: return anchorOf(s).latitude;
    case LongitudeRole: return anchorOf(s).longitude;
    case AltitudeRole: return known(altitudeOf(s));
    case AltitudeTypeRole: return altitudeTypeName(altitudeTypeOf(s));
    case SpeedRole: return known(speedOf(s));
    case TurnTypeRole: return w ? turnTypeName(w->turnType) : QVariant();
    case AcceptanceRadiusRole: return w ? w->acceptanceRadius : QVariant();
    case ActionCountRole: return w ? int(w->actions.size()) : 0;
    case ActionsSummaryRole: return w ? describeActions(w->actions) : QString();
    case ActionMarksRole: {
        if (!w)
            return 0;
        int marks = 0;
        for (const WaypointAction &a : w->actions) {
            const bool camera = std::holds_alternative<CameraTriggerAction>(a) || std::holds_alternative<CameraSeriesByTimeAction>(a)
                                || std::holds_alternative<CameraSeriesByDistanceAction>(a) || std::holds_alternative<PanoramaAction>(a);
            marks |= camera ? CameraMark : OtherActionMark;
        }
        return marks;
    }
    case ActionsRole: {
        QVariantList list;
        if (w)
            for (const auto &a : w->actions)
                list << actionToVariant(a);
        return list;
    }
    case PolygonRole: {
        QVariantList list;
        for (const GeoPoint &g : figureOf(s))
            list << QVariantMap{{"latitude", g.latitude}, {"longitude", g.longitude}};
        return list;
    }
    case ScanParametersRole: return w ? QVariant() : parametersToVariant(s);
    default: return {};
    }
}

std::optional<AreaScanOutcome> RouteModel::scanPlan(int row) const
{
    if (row < 0 || row >= count())
        return std::nullopt;
    const std::optional<AreaScan> scan = scanOf(segment(row), m_route.settings.profile.cameras);
    return scan ? std::optional<AreaScanOutcome>(m_scanPlans.outcome(*scan)) : std::nullopt;
}

QString RouteModel::plannedStartText() const
{
    const std::optional<QDateTime> &start = m_route.settings.plannedStart;
    return start ? start->toTimeZone(QTimeZone::systemTimeZone()).toString(QStringLiteral("yyyy-MM-dd HH:mm")) : QString();
}

QStringList RouteModel::authorisedZones() const
{
    QStringList zones;
    for (const auto &entry : m_route.settings.authorisations)
        zones.append(entry.first);
    return zones;
}

QString RouteModel::authorisationFor(const QString &identifier) const
{
    const auto it = m_route.settings.authorisations.find(identifier);
    return it == m_route.settings.authorisations.end() ? QString() : it->second;
}

QString RouteModel::segmentLabelFor(int row, const Segment &s)
{
    return segmentLabel(row, s);
}

void RouteModel::insertSegments(int row, std::vector<Segment> segments)
{
    if (segments.empty())
        return;
    beginInsertRows({}, row, row + int(segments.size()) - 1);
    m_route.segments.insert(m_route.segments.begin() + row, std::make_move_iterator(segments.begin()),
                            std::make_move_iterator(segments.end()));
    endInsertRows();
    if (row + int(segments.size()) < count())  // rows after the insertion were renumbered
        emit dataChanged(index(row + int(segments.size())), index(count() - 1), {SequenceRole});
    emit countChanged();
    emit routeEdited();
}

std::vector<Segment> RouteModel::takeSegments(const std::vector<int> &rows)
{
    std::vector<Segment> taken;
    taken.reserve(rows.size());
    for (int r : rows)
        taken.push_back(std::move(m_route.segments[size_t(r)]));
    const auto runs = contiguousRuns(rows);
    auto compact = [&] {
        size_t out = 0, next = 0;
        for (size_t i = 0; i < m_route.segments.size(); ++i) {
            if (next < rows.size() && int(i) == rows[next]) { ++next; continue; }
            if (out != i) m_route.segments[out] = std::move(m_route.segments[i]);
            ++out;
        }
        m_route.segments.resize(out);
    };
    if (runs.size() > kMaxRunsSignalled) {
        beginResetModel();
        compact();
        endResetModel();
    } else {
        for (auto it = runs.rbegin(); it != runs.rend(); ++it) {
            beginRemoveRows({}, it->first, it->second);
            m_route.segments.erase(m_route.segments.begin() + it->first, m_route.segments.begin() + it->second + 1);
            endRemoveRows();
        }
        if (!rows.empty() && rows.front() < count())
            emit dataChanged(index(rows.front()), index(count() - 1), {SequenceRole});
    }
    emit countChanged();
    emit routeEdited();
    return taken;
}

void RouteModel::restoreSegments(const std::vector<int> &rows, std::vector<Segment> segments)
{
    const auto runs = contiguousRuns(rows);
    if (runs.size() > kMaxRunsSignalled) {
        beginResetModel();
        std::vector<Segment> merged;
        merged.reserve(m_route.segments.size() + segments.size());
        size_t old = 0, next = 0;
        for (size_t i = 0; i < m_route.segments.size() + segments.size(); ++i) {
            if (next < rows.size() && int(i) == rows[next])
                merged.push_back(std::move(segments[next++]));
            else
                merged.push_back(std::move(m_route.segments[old++]));
        }
        m_route.segments = std::move(merged);
        endResetModel();
        emit countChanged();
        emit routeEdited();
        return;
    }
    size_t k = 0;
    for (const auto &[first, last] : runs) {
        std::vector<Segment> part;
        for (int r = first; r <= last; ++r)
            part.push_back(std::move(segments[k++]));
        insertSegments(first, std::move(part));
    }
}

void RouteModel::replaceSegments(const std::vector<int> &rows, const std::vector<Segment> &values)
{
    for (size_t i = 0; i < rows.size(); ++i)
        m_route.segments[size_t(rows[i])] = values[i];
    emitChanged(rows, {});
}

void RouteModel::permute(const std::vector<int> &order)
{
    emit layoutAboutToBeChanged({}, QAbstractItemModel::NoLayoutChangeHint);
    std::vector<Segment> next;
    next.reserve(order.size());
    std::vector<int> whereNow(order.size());
    for (size_t i = 0; i < order.size(); ++i) {
        next.push_back(std::move(m_route.segments[size_t(order[i])]));
        whereNow[size_t(order[i])] = int(i);
    }
    m_route.segments = std::move(next);
    const QModelIndexList persistent = persistentIndexList();
    QModelIndexList moved;
    moved.reserve(persistent.size());
    for (const QModelIndex &p : persistent)
        moved << index(whereNow[size_t(p.row())]);
    changePersistentIndexList(persistent, moved);
    emit layoutChanged({}, QAbstractItemModel::NoLayoutChangeHint);
    emit routeEdited();
}

void RouteModel::setSettings(const RouteSettings &settings)
{
    m_route.settings = settings;
    emit settingsChanged();
    emit routeEdited();
}

void RouteModel::resetRoute(Route route)
{
    const int before = count();
    beginResetModel();
    m_route = std::move(route);
    endResetModel();
    if (before != count())
        emit countChanged();
    emit settingsChanged();
    emit routeEdited();
}

void RouteModel::emitChanged(const std::vector<int> &rows, const QList<int> &roles)
{
    for (const auto &[first, last] : contiguousRuns(rows))
        emit dataChanged(index(first), index(last), roles);
    emit routeEdited();
}

} // namespace sortie::mission
