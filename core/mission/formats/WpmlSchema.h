#pragma once

#include "WpmlFormat.h"

#include <QString>

#include <optional>

// The names WPML uses for its enumerations (DJI Cloud API, DJI WPML "Common Elements"), shared by
// the writer and the reader so both spell them once.
namespace sortie::mission::formats::wpml {

inline const QString kNamespace = QStringLiteral("http://www.dji.com/wpmz/1.0.2");
inline const QString kKmlNamespace = QStringLiteral("http://www.opengis.net/kml/2.2");

enum class TurnMode { Coordinated, StopStraight, StopCurved, PassCurved };
enum class HeadingMode { FollowWayline, Manually, Fixed, SmoothTransition, TowardPoi };
enum class TriggerType { ReachPoint, BetweenAdjacentPoints, MultipleTiming, MultipleDistance };
enum class ActuatorFunc { TakePhoto, StartRecord, StopRecord, GimbalRotate, RotateYaw, Hover };
enum class FinishAction { GoHome, NoAction, AutoLand, GotoFirstWaypoint };

inline QString turnModeName(TurnMode m)
{
    switch (m) {
    case TurnMode::Coordinated: return QStringLiteral("coordinateTurn");
    case TurnMode::StopStraight: return QStringLiteral("toPointAndStopWithDiscontinuityCurvature");
    case TurnMode::StopCurved: return QStringLiteral("toPointAndStopWithContinuityCurvature");
    case TurnMode::PassCurved: return QStringLiteral("toPointAndPassWithContinuityCurvature");
    }
    return {};
}

inline QString headingModeName(HeadingMode m)
{
    switch (m) {
    case HeadingMode::FollowWayline: return QStringLiteral("followWayline");
    case HeadingMode::Manually: return QStringLiteral("manually");
    case HeadingMode::Fixed: return QStringLiteral("fixed");
    case HeadingMode::SmoothTransition: return QStringLiteral("smoothTransition");
    case HeadingMode::TowardPoi: return QStringLiteral("towardPOI");
    }
    return {};
}

inline QString triggerTypeName(TriggerType t)
{
    switch (t) {
    case TriggerType::ReachPoint: return QStringLiteral("reachPoint");
    case TriggerType::BetweenAdjacentPoints: return QStringLiteral("betweenAdjacentPoints");
    case TriggerType::MultipleTiming: return QStringLiteral("multipleTiming");
    case TriggerType::MultipleDistance: return QStringLiteral("multipleDistance");
    }
    return {};
}

inline QString actuatorFuncName(ActuatorFunc f)
{
    switch (f) {
    case ActuatorFunc::TakePhoto: return QStringLiteral("takePhoto");
    case ActuatorFunc::StartRecord: return QStringLiteral("startRecord");
    case ActuatorFunc::StopRecord: return QStringLiteral("stopRecord");
    case ActuatorFunc::GimbalRotate: return QStringLiteral("gimbalRotate");
    case ActuatorFunc::RotateYaw: return QStringLiteral("rotateYaw");
    case ActuatorFunc::Hover: return QStringLiteral("hover");
    }
    return {};
}

inline QString finishActionName(FinishAction a)
{
    switch (a) {
    case FinishAction::GoHome: return QStringLiteral("goHome");
    case FinishAction::NoAction: return QStringLiteral("noAction");
    case FinishAction::AutoLand: return QStringLiteral("autoLand");
    case FinishAction::GotoFirstWaypoint: return QStringLiteral("gotoFirstWaypoint");
    }
    return {};
}

// waylines.wpml's executeHeightMode: EGM96 heights are executed relative to take-off, WGS-84 ones as
// ellipsoidal heights (see WpmlFormat.h).
inline QString executeHeightModeName(WpmlHeightMode m)
{
    switch (m) {
    case WpmlHeightMode::AboveGroundLevel: return QStringLiteral("realTimeFollowSurface");
    case WpmlHeightMode::Wgs84: return QStringLiteral("WGS84");
    case WpmlHeightMode::RelativeToTakeoff:
    case WpmlHeightMode::Egm96: break;
    }
    return QStringLiteral("relativeToStartPoint");
}

// template.kml's heightMode.
inline QString templateHeightModeName(WpmlHeightMode m)
{
    switch (m) {
    case WpmlHeightMode::RelativeToTakeoff: return QStringLiteral("relativeToStartPoint");
    case WpmlHeightMode::Egm96:
    case WpmlHeightMode::Wgs84: return QStringLiteral("EGM96");
    case WpmlHeightMode::AboveGroundLevel: return QStringLiteral("realTimeFollowSurface");
    }
    return {};
}

template<typename E, typename Name>
std::optional<E> parseName(const QString &text, Name name, std::initializer_list<E> values)
{
    for (E v : values)
        if (name(v) == text)
            return v;
    return std::nullopt;
}

} // namespace sortie::mission::formats::wpml
