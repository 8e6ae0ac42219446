#pragma once

#include "MissionError.h"

#include <QByteArray>
#include <QString>

#include <optional>
#include <vector>

namespace sortie::preflight {

// What the program checks for an item itself; Manual is one the operator ticks.
enum class Check { Manual, Link, GpsFix, Satellites, Battery, Home, RouteOnBoard, RouteCheck, Camera };

// The commands an item holds back until it passes (a bit mask of these).
enum Gate : unsigned { GateArm = 1u, GateAuto = 2u };

struct ChecklistItem
{
    Check check = Check::Manual;
    QString title;                   // the file's words; empty for a checked item: the program names it
    std::optional<double> minimum;   // GpsFix (fix type), Satellites (count), Battery (percent)
    bool required = true;            // false: shown, never holds a command back
    unsigned gates = GateArm | GateAuto;
};

// One vehicle type's checklist, in the order the operator works through it.
struct Checklist
{
    QString name;
    std::vector<ChecklistItem> items;
};

// The file's spelling of a check ("gps_fix"); Manual has none (an item without `check`).
const char *checkName(Check check);

// What holds when the operator has written none: link, 3D fix, 8 satellites, 60 % battery and home
// set, for Arm and Auto; the route on board the one planned, for Auto. Advisory (shown, holding
// nothing back): the open route's check, the camera, and three reminders to tick (propellers, the
// area, the payload) — an operator's own file makes any of them required.
Checklist defaultChecklist();

// A checklist file (docs/preflight.md): JSON, {"name": …, "items": [{"check": "satellites",
// "minimum": 10}, {"title": "Propellers tight"}, …]}. A syntax error names its line and column;
// an item that cannot be used its JSON path ("/items/3/check: unknown value \"wind\"") — the file
// is refused whole, so a checklist is never quietly shorter than the one written.
mission::Result<Checklist> readChecklist(const QByteArray &json);

} // namespace sortie::preflight
