#include "HciMissionRoute.h"

#include "Domain.pb.h"

namespace sortie::vehicle {

namespace pb = com::ugcs::ucs::proto;

pb::Route hciRouteFor(const pb::Vehicle &vehicle, const std::vector<MissionItem> &items, const QString &name)
{
    pb::Route route;
    route.set_name(name.toStdString());
    if (vehicle.has_profile())
        *route.mutable_vehicleprofile() = vehicle.profile();
    route.set_checkaerodromenfz(false);
    route.set_checkcustomnfz(false);
    for (const MissionItem &item : items) {
        auto *segment = route.add_segments();
        segment->set_algorithmclassname("com.ugcs.ucs.service.routing.impl.WaypointAlgorithm");
        auto *figure = segment->mutable_figure();
        figure->set_type(pb::FT_POINT);
        auto *point = figure->add_points();
        point->set_latitude(item.latitude);
        point->set_longitude(item.longitude);
        point->set_aglaltitude(item.altitude);
        point->set_altitudetype(pb::AT_AGL);
        auto *altitudeType = segment->add_parametervalues();
        altitudeType->set_name("altitudeType");
        altitudeType->set_value("AGL");
        if (item.speed > 0) {
            auto *speed = segment->add_parametervalues();
            speed->set_name("speed");
            speed->set_value(QString::number(item.speed).toStdString());
        }
    }
    return route;
}

QString hciProcessingProblem(const pb::ProcessedRoute &route)
{
    for (int i = 0; i < route.segments_size(); ++i) {
        const pb::ProcessedSegment &s = route.segments(i);
        if (s.status() == pb::RPS_PROCESSED)
            continue;
        QString why;
        for (const auto &m : s.messageset().messages()) {
            if (m.severity() == pb::MS_ERROR || why.isEmpty())
                why = QString::fromStdString(m.defaulttext());
            if (m.severity() == pb::MS_ERROR)
                break;
        }
        if (why.isEmpty())
            why = QStringLiteral("the server could not process it");
        return QStringLiteral("Waypoint %1: %2").arg(i + 1).arg(why);
    }
    return {};
}

} // namespace sortie::vehicle
