#pragma once

#include <QObject>

// The enumerations an edit takes, in one Qt namespace so that QML passes them typed
// (MissionEnums.Amsl) to the RouteEditor instead of strings the editor would parse back.
namespace sortie::mission::MissionEnums {
Q_NAMESPACE

enum class AltitudeType { Agl, Amsl };  // above ground level / above mean sea level
Q_ENUM_NS(AltitudeType)

enum class TurnType { StopAndTurn, Straight, Spline, BankTurn };
Q_ENUM_NS(TurnType)

// A continuous gesture (a drag, a dial) sends Continuing while it lasts and Done when it ends:
// the steps of one gesture merge into a single undo step. One-shot edits are Done.
enum class EditStep { Done, Continuing };
Q_ENUM_NS(EditStep)

} // namespace sortie::mission::MissionEnums

namespace sortie::mission {
using MissionEnums::AltitudeType;
using MissionEnums::EditStep;
using MissionEnums::TurnType;
} // namespace sortie::mission
