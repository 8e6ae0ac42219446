#pragma once

#include "Checklist.h"

#include <optional>

namespace sortie::preflight {

// What the program knows of a vehicle when it checks its list. A value not known is missing
// (nullopt), never 0: a vehicle that has sent no satellite count fails "8 satellites" as missing,
// not as "0 satellites".
struct PreflightFacts
{
    bool linkUp = false;                      // connected, its telemetry fresh
    std::optional<double> gpsFix;             // 0 none, 2 2D, 3 3D, 4 RTK float, 5 RTK fixed
    std::optional<double> satellites;
    std::optional<double> batteryPercent;     // 0..100
    std::optional<bool> homeSet;
    bool homeReportable = true;               // false: the vehicle's link never reports a home (HCI)
    std::optional<bool> routeOnBoard;         // nullopt: Sortie has given the vehicle no route
    std::optional<int> routeErrors;           // nullopt: the vehicle's route is not the open one
    std::optional<bool> cameraPresent;
};

enum class Outcome {
    Pass,     // the program checked it, and it holds
    Fail,     // the program checked it, and it does not
    Missing,  // the program cannot tell: the value is not known
    Ticked,   // the operator ticked it
    Unticked, // the operator has not (yet)
    NotReported, // the vehicle's link never reports it: shown, never holding a command back
};

struct ItemVerdict
{
    Outcome outcome = Outcome::Missing;
    std::optional<double> value; // what was measured, for the view ("6 satellites"); nullopt: nothing
};

// The verdict on one item. Telemetry items need the link: without it their values are old, so
// they are missing.
ItemVerdict judge(const ChecklistItem &item, const PreflightFacts &facts, bool ticked);

// Whether the item holds back a command of `gate`: required, for that gate, and not passed (what
// the link never reports cannot be checked, and holds nothing back).
bool holdsBack(const ChecklistItem &item, const ItemVerdict &verdict, Gate gate);

} // namespace sortie::preflight
