#include "TerrainProfileModel.h"

#include "RouteModel.h"

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
    emit profileChanged();
}

QString TerrainProfileModel::sourceText() const
{
    if (!m_service)
        return tr("no terrain source");
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

} // namespace sortie::ui
