#include "Waypoint.h"

namespace sortie::mission {

QString turnTypeName(TurnType type)
{
    switch (type) {
    case TurnType::StopAndTurn: return QStringLiteral("StopAndTurn");
    case TurnType::Straight: return QStringLiteral("Straight");
    case TurnType::Spline: return QStringLiteral("Spline");
    case TurnType::BankTurn: return QStringLiteral("BankTurn");
    }
    return {};
}

bool parseTurnType(const QString &name, TurnType *out)
{
    for (TurnType t : {TurnType::StopAndTurn, TurnType::Straight, TurnType::Spline, TurnType::BankTurn}) {
        if (name.compare(turnTypeName(t), Qt::CaseInsensitive) == 0) {
            *out = t;
            return true;
        }
    }
    return false;
}

QString roleName(WaypointRole role)
{
    switch (role) {
    case WaypointRole::Pass: return QStringLiteral("waypoint");
    case WaypointRole::Takeoff: return QStringLiteral("takeoff");
    case WaypointRole::Land: return QStringLiteral("land");
    }
    return {};
}

bool parseRole(const QString &name, WaypointRole *out)
{
    for (WaypointRole r : {WaypointRole::Pass, WaypointRole::Takeoff, WaypointRole::Land}) {
        if (name == roleName(r)) {
            *out = r;
            return true;
        }
    }
    return false;
}

} // namespace sortie::mission
