#include "ProcessedPlanModel.h"

namespace sortie::mission {

namespace {
QString frameName(AltitudeFrame f)
{
    switch (f) {
    case AltitudeFrame::Wgs84: return QStringLiteral("WGS84");
    case AltitudeFrame::Agl: return QStringLiteral("AGL");
    case AltitudeFrame::Rangefinder: return QStringLiteral("RANGEFINDER");
    case AltitudeFrame::SmartAgl: return QStringLiteral("SMART_AGL");
    }
    return {};
}

QString statusName(ProcessingStatus s)
{
    switch (s) {
    case ProcessingStatus::Modified: return QStringLiteral("modified");
    case ProcessingStatus::Invalid: return QStringLiteral("invalid");
    case ProcessingStatus::Marked: return QStringLiteral("marked");
    case ProcessingStatus::Processed: return QStringLiteral("processed");
    }
    return {};
}
}

ProcessedPlanModel::ProcessedPlanModel(QObject *parent) : QAbstractListModel(parent) {}

int ProcessedPlanModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QHash<int, QByteArray> ProcessedPlanModel::roleNames() const
{
    return {{LatitudeRole, "latitude"}, {LongitudeRole, "longitude"}, {AltitudeAmslRole, "altitudeAmsl"},
            {GroundElevationRole, "groundElevation"}, {HeightAboveGroundRole, "heightAboveGround"}, {FrameRole, "frame"},
            {SpeedRole, "speed"}, {KindRole, "kind"}, {ConnectionRole, "connection"}, {SegmentRole, "segment"},
            {RouteRowRole, "routeRow"}, {StatusRole, "status"}};
}

QVariant ProcessedPlanModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const ProcessedWaypoint &w = m_plan.waypoints[size_t(index.row())];
    const ProcessedSegment &s = m_plan.segments[size_t(w.segment)];
    switch (role) {
    case LatitudeRole: return w.position.latitude;
    case LongitudeRole: return w.position.longitude;
    case AltitudeAmslRole: return w.altitudeAmsl;
    case GroundElevationRole: return w.groundElevation;
    case HeightAboveGroundRole: return w.altitudeAmsl - w.groundElevation;
    case FrameRole: return frameName(w.frame);
    case SpeedRole: return w.speed;
    case KindRole: return roleName(w.role);
    case ConnectionRole: return w.connection;
    case SegmentRole: return w.segment;
    case RouteRowRole: return s.routeRow;
    case StatusRole: return statusName(s.status);
    default: return {};
    }
}

void ProcessedPlanModel::setPlan(ProcessedPlan plan)
{
    beginResetModel();
    m_plan = std::move(plan);
    endResetModel();
    emit planChanged();
}

QStringList ProcessedPlanModel::errors() const
{
    QStringList out;
    for (size_t i = 0; i < m_plan.segments.size(); ++i)
        for (const ProcessedMessage &m : m_plan.segments[i].messages)
            if (m.error)
                out << QStringLiteral("Segment %1: %2").arg(i + 1).arg(m.text);
    return out;
}

} // namespace sortie::mission
