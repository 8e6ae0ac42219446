#include "TerrainProfileModel.h"

#include "RouteModel.h"
#include "TypedNumber.h"

#include <algorithm>
#include <cmath>

namespace sortie::ui {

TerrainProfileModel::TerrainProfileModel(QObject *parent) : QObject(parent)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(16);
    connect(&m_timer, &QTimer::timeout, this, &TerrainProfileModel::recomputeNow);
}

QObject *TerrainProfileModel::routeModel() const
{
    return m_model;
}

void TerrainProfileModel::setRouteModel(QObject *model)
{
    auto *m = qobject_cast<mission::RouteModel *>(model);
    if (m == m_model)
        return;
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = m;
    if (m) {
        connect(m, &mission::RouteModel::routeEdited, this, &TerrainProfileModel::schedule);
        connect(m, &mission::RouteModel::settingsChanged, this, &TerrainProfileModel::schedule);
    }
    emit routeModelChanged();
    schedule();
}

void TerrainProfileModel::setService(terrain::ElevationService *service)
{
    if (service == m_service)
        return;
    if (m_service)
        disconnect(m_service, nullptr, this, nullptr);
    m_service = service;
    if (service)
        connect(service, &terrain::ElevationService::changed, this, &TerrainProfileModel::schedule);
    emit serviceChanged();
    schedule();
}

void TerrainProfileModel::setStep(double metres)
{
    if (!(metres > 0) || metres == m_step)
        return;
    m_step = metres;
    emit stepChanged();
    schedule();
}

void TerrainProfileModel::setDelay(int milliseconds)
{
    if (milliseconds == m_timer.interval())
        return;
    m_timer.setInterval(std::max(0, milliseconds));
    emit delayChanged();
}

void TerrainProfileModel::schedule()
{
    if (!m_timer.isActive())
        m_timer.start();  // a running timer already covers this change: at most one recomputation per delay
}

void TerrainProfileModel::recomputeNow()
{
    m_timer.stop();
    ++m_recomputes;
    if (m_model && m_service) {
        m_route = terrain::profileRouteOf(m_model->route());
        m_profile = terrain::computeProfile(m_route, *m_service, m_step);
    } else {
        m_route = {};
        m_profile = {};
    }
    m_rows.clear();
    for (size_t i = 0; i < m_route.waypoints.size(); ++i) {
        const int row = m_route.waypoints[i].row;
        if (row < 0)
            continue;
        if (size_t(row) >= m_rows.size())
            m_rows.resize(size_t(row) + 1);
        RowPoints &r = m_rows[size_t(row)];
        if (r.count++ == 0)
            r.first = int(i);
    }
    emit profileChanged();
}

QString TerrainProfileModel::sourceText() const
{
    if (!m_service)
        return tr("no terrain source");
    if (m_profile.ground.empty())  // nothing asked yet: the sources that will be
        return m_service->sourceNames().join(QStringLiteral(", "));
    // Name the sources that gave the ground, in order; "none" when no source had data.
    std::vector<int> used;
    for (const terrain::GroundSample &g : m_profile.ground)
        if (g.source >= 0 && std::find(used.begin(), used.end(), g.source) == used.end())
            used.push_back(g.source);
    std::sort(used.begin(), used.end());
    QStringList names;
    for (int i : used)
        names << m_service->sourceName(i);
    QString text = names.isEmpty() ? tr("no terrain data (tried: %1)").arg(m_service->triedText()) : names.join(QStringLiteral(", "));
    if (m_profile.pending)
        text += tr(" · loading…");
    return text;
}

double TerrainProfileModel::minClearance() const
{
    return m_profile.minClearance ? m_profile.minClearance->clearance : std::nan("");
}

int TerrainProfileModel::rowOfLeg(int leg) const
{
    return leg >= 0 && size_t(leg) < m_route.waypoints.size() ? m_route.waypoints[size_t(leg)].row : -1;
}

int TerrainProfileModel::sampleAt(double distance) const
{
    const auto &pts = m_profile.path.points;
    if (pts.empty())
        return -1;
    const auto it = std::lower_bound(pts.begin(), pts.end(), distance,
                                     [](const terrain::PathSamplePoint &p, double d) { return p.distance < d; });
    if (it == pts.end())
        return int(pts.size()) - 1;
    if (it == pts.begin())
        return 0;
    const auto before = it - 1;
    return int((distance - before->distance <= it->distance - distance ? before : it) - pts.begin());
}

TerrainProfileModel::RowPoints TerrainProfileModel::pointsOfRow(int row) const
{
    if (row < 0 || size_t(row) >= m_rows.size() || m_profile.waypoints.size() != m_route.waypoints.size())
        return {};
    return m_rows[size_t(row)];
}

QVariant TerrainProfileModel::altitudeOfRow(int row, mission::AltitudeType frame) const
{
    const RowPoints points = pointsOfRow(row);
    if (points.count == 0)
        return {};
    const terrain::ProfileWaypoint &first = m_route.waypoints[size_t(points.first)];
    const terrain::HeightReference wanted =
        frame == mission::AltitudeType::Amsl ? terrain::HeightReference::Amsl : terrain::HeightReference::AboveTerrain;
    if (first.reference == wanted)  // its own type: known without the ground
        return first.altitude;
    if (points.count > 1)
        return {};
    const terrain::WaypointTerrain &w = m_profile.waypoints[size_t(points.first)];
    const double value = frame == mission::AltitudeType::Amsl ? w.altitudeAmsl : w.altitudeAgl;
    return std::isfinite(value) ? QVariant(value) : QVariant();
}

QString TerrainProfileModel::groundTextOfRow(int row) const
{
    const RowPoints points = pointsOfRow(row);
    if (points.count == 0)
        return {};
    double low = INFINITY, high = -INFINITY;
    bool pending = false;
    for (int i = points.first; i < points.first + points.count; ++i) {
        const terrain::GroundSample &g = m_profile.waypoints[size_t(i)].ground;
        if (g.hasValue()) {
            low = std::min(low, g.ground);
            high = std::max(high, g.ground);
        }
        pending |= g.status == terrain::SampleStatus::Pending;
    }
    if (low > high)
        return pending ? QStringLiteral("…") : QStringLiteral("—");
    if (high - low < 0.05)
        return i18n::formatTypedNumber(low, 1);  // in the language's format, as the table's other numbers
    return QStringLiteral("%1–%2").arg(i18n::formatTypedNumber(low, 0), i18n::formatTypedNumber(high, 0));  // fits the column
}

QString TerrainProfileModel::groundToolTipOfRow(int row) const
{
    const RowPoints points = pointsOfRow(row);
    if (points.count == 0 || !m_service)
        return {};
    QStringList sources;
    bool missing = false, pending = false;
    for (int i = points.first; i < points.first + points.count; ++i) {
        const terrain::GroundSample &g = m_profile.waypoints[size_t(i)].ground;
        if (g.hasValue()) {
            const QString name = m_service->sourceName(g.source);
            if (!sources.contains(name))
                sources << name;
        }
        missing |= g.status == terrain::SampleStatus::NoData;
        pending |= g.status == terrain::SampleStatus::Pending;
    }
    const QString where = points.count == 1 ? tr("under this waypoint") : tr("under this segment's points");
    if (sources.isEmpty())
        return pending ? tr("Asking for the ground %1…").arg(where)
                       : tr("No terrain data %1 (tried: %2)").arg(where, m_service->triedText());
    QString text = tr("Ground %1, metres above sea level (EGM96), from %2").arg(where, sources.join(QStringLiteral(", ")));
    if (missing)
        text += tr("; some points have no data (tried: %1)").arg(m_service->triedText());
    return text;
}

} // namespace sortie::ui
