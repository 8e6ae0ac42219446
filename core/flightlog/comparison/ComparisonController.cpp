#include "ComparisonController.h"

#include "LanguageChange.h"
#include "MissionFiles.h"
#include "ReplayController.h"

#include <QDateTime>
#include <QUrl>

#include <cmath>

namespace sortie::flightlog {

int deviationLevel(double metres)
{
    if (!std::isfinite(metres) || metres <= kDeviationFine)
        return 0;
    return metres <= kDeviationWarn ? 1 : 2;
}

namespace {
QVariant metres(double v)
{
    return std::isfinite(v) ? QVariant(QString::number(v, 'f', 1)) : QVariant(QStringLiteral("—"));
}
} // namespace

void ComparisonLegModel::reset(const RouteComparison *comparison)
{
    beginResetModel();
    m_c = comparison;
    endResetModel();
}

int ComparisonLegModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() || !m_c ? 0 : int(m_c->legs.size());
}

ComparisonLegModel::ComparisonLegModel(QObject *parent)
    : QAbstractListModel(parent)
{
    i18n::refreshOnLanguageChange(this);
}

QVariant ComparisonLegModel::data(const QModelIndex &index, int role) const
{
    if (!m_c || !checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const LegDeviation &l = m_c->legs[size_t(index.row())];
    switch (role) {
    case LegRole: return QStringLiteral("%1 → %2").arg(l.from + 1).arg(l.to + 1);
    case SamplesRole: return l.samples;
    case MaxCrossTrackRole: return metres(l.maxCrossTrack);
    case MeanCrossTrackRole: return metres(l.meanCrossTrack);
    case MaxAltitudeRole: return metres(l.maxAltitude);
    case MeanAltitudeRole: return metres(l.meanAltitude);
    case ReachedRole: {
        const WaypointPassage &w = m_c->waypoints[size_t(l.to)];
        return w.reachedAt ? QDateTime::fromMSecsSinceEpoch(*w.reachedAt, Qt::UTC).toString(QStringLiteral("HH:mm:ss"))
                           : QObject::tr("missed");
    }
    case LevelRole: return l.samples ? std::max(deviationLevel(l.maxCrossTrack), deviationLevel(l.maxAltitude)) : 2;
    default: return {};
    }
}

QHash<int, QByteArray> ComparisonLegModel::roleNames() const
{
    return {{LegRole, "leg"}, {SamplesRole, "samples"}, {MaxCrossTrackRole, "maxCrossTrack"},
            {MeanCrossTrackRole, "meanCrossTrack"}, {MaxAltitudeRole, "maxAltitude"}, {MeanAltitudeRole, "meanAltitude"},
            {ReachedRole, "reached"}, {LevelRole, "level"}};
}

void ComparisonTrackModel::reset(const RouteComparison *comparison)
{
    beginResetModel();
    m_c = comparison;
    endResetModel();
}

int ComparisonTrackModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() || !m_c ? 0 : int(m_c->track.size());
}

QVariant ComparisonTrackModel::data(const QModelIndex &index, int role) const
{
    if (!m_c || !checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const TrackDeviation &t = m_c->track[size_t(index.row())];
    switch (role) {
    case LatitudeRole: return t.latitude;
    case LongitudeRole: return t.longitude;
    case DeviationRole: return t.crossTrack;
    case LevelRole: return deviationLevel(t.crossTrack);
    default: return {};
    }
}

QHash<int, QByteArray> ComparisonTrackModel::roleNames() const
{
    return {{LatitudeRole, "latitude"}, {LongitudeRole, "longitude"}, {DeviationRole, "deviation"}, {LevelRole, "level"}};
}

ComparisonController::ComparisonController(ReplayController *replay, QObject *parent)
    : QObject(parent)
    , m_replay(replay)
{
    connect(replay, &ReplayController::loadedChanged, this, &ComparisonController::clear);
}

bool ComparisonController::compare(const QString &routeFile, int vehicleRow)
{
    clear();
    const QString path = routeFile.startsWith(QLatin1String("file:")) ? QUrl(routeFile).toLocalFile() : routeFile;
    if (!m_replay || !m_replay->log()) {
        m_error = tr("Open a flight log first.");
    } else if (const auto loaded = mission::formats::loadMission(path); !loaded) {
        m_error = loaded.error().toString();
    } else if (loaded->mission.routes.empty()) {
        m_error = tr("%1 holds no route.").arg(path);
    } else if (vehicleRow < 0 && m_replay->log()->vehicles().size() != 1) {
        m_error = tr("Choose the vehicle to compare on the map or in the list.");
    } else {
        ComparisonResult r = compareRoute(*m_replay->log(), vehicleRow < 0 ? 0 : vehicleRow, loaded->mission.routes.front());
        m_error = r.error;
        m_result = std::move(r.comparison);
    }
    m_legs.reset(m_result ? &*m_result : nullptr);
    m_track.reset(m_result ? &*m_result : nullptr);
    emit changed();
    return m_result.has_value();
}

void ComparisonController::clear()
{
    if (!m_result && m_error.isEmpty())
        return;
    m_legs.reset(nullptr);
    m_track.reset(nullptr);
    m_result.reset();
    m_error.clear();
    emit changed();
}

QString ComparisonController::summary() const
{
    if (!m_result)
        return {};
    const RouteComparison &c = *m_result;
    return tr("%1 on \"%2\": %3 of %4 waypoints reached; cross-track max %5 m, mean %6 m; altitude max %7 m")
        .arg(c.vehicleName, c.routeName).arg(c.reached).arg(c.waypoints.size())
        .arg(c.maxCrossTrack, 0, 'f', 1).arg(c.meanCrossTrack, 0, 'f', 1).arg(c.maxAltitude, 0, 'f', 1);
}

} // namespace sortie::flightlog
