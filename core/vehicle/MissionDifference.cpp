#include "MissionDifference.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <QCoreApplication>

namespace sortie::vehicle {

namespace {

bool sameAction(const MissionAction &a, const MissionAction &b)
{
    if (a.type != b.type || a.parameters.keys() != b.parameters.keys())
        return false;
    for (auto it = a.parameters.begin(); it != a.parameters.end(); ++it) {
        const QVariant &other = b.parameters.value(it.key());
        bool na = false, nb = false;
        const double x = it.value().toDouble(&na), y = other.toDouble(&nb);
        if (na && nb && it.value().typeId() != QMetaType::QString && other.typeId() != QMetaType::QString) {
            if (std::abs(x - y) > 1e-9 * std::max(1.0, std::abs(x)))
                return false;
        } else if (it.value().toString() != other.toString()) {
            return false;
        }
    }
    return true;
}

} // namespace

QString missionDifference(const std::vector<MissionItem> &sent, const std::vector<MissionItem> &back)
{
    if (sent.size() != back.size())
        return QCoreApplication::translate("MissionDifference", "the vehicle holds %n waypoint(s), %1 were sent", nullptr, int(back.size())).arg(sent.size());
    constexpr double kAngle = 1e-3 / 6378137.0 * (180.0 / std::numbers::pi); // a millimetre on the ground, in degrees
    for (size_t i = 0; i < sent.size(); ++i) {
        const MissionItem &s = sent[i], &b = back[i];
        const QString where = QCoreApplication::translate("MissionDifference", "waypoint %1: ").arg(i + 1);
        if (std::abs(s.latitude - b.latitude) > kAngle || std::abs(s.longitude - b.longitude) > kAngle)
            return where + QCoreApplication::translate("MissionDifference", "the vehicle holds another position");
        if (std::abs(s.altitude - b.altitude) > 1e-3)
            return where + QCoreApplication::translate("MissionDifference", "altitude %1 m, sent %2 m").arg(b.altitude).arg(s.altitude);
        if (s.speed > 0 && std::abs(s.speed - b.speed) > 1e-3)
            return where + QCoreApplication::translate("MissionDifference", "speed %1 m/s, sent %2 m/s").arg(b.speed).arg(s.speed);
        if (s.acceptanceRadius > 0 && std::abs(s.acceptanceRadius - b.acceptanceRadius) > 1e-3)
            return where + QCoreApplication::translate("MissionDifference", "acceptance radius %1 m, sent %2 m").arg(b.acceptanceRadius).arg(s.acceptanceRadius);
        if (s.actions.size() != b.actions.size())
            return where + QCoreApplication::translate("MissionDifference", "%n action(s), sent %1", nullptr, int(b.actions.size())).arg(s.actions.size());
        for (size_t a = 0; a < s.actions.size(); ++a) {
            if (!sameAction(s.actions[a], b.actions[a]))
                return where + QCoreApplication::translate("MissionDifference", "action %1 (%2) differs").arg(a + 1).arg(s.actions[a].type);
        }
    }
    return {};
}

} // namespace sortie::vehicle
