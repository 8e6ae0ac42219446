#include "Checklist.h"

#include "JsonCursor.h"

#include <QCoreApplication>

#include <cmath>

namespace sortie::preflight {

using mission::formats::Json;
using mission::formats::JsonCursor;
using mission::formats::JsonPathError;

namespace {
// In Check's order; Manual has no name in a file (an item without `check`).
const char *const kCheckNames[] = {"", "link", "gps_fix", "satellites", "battery", "home", "route_on_board", "route_check", "camera"};
const char *const kGateNames[] = {"arm", "auto"};

bool takesMinimum(Check check)
{
    return check == Check::GpsFix || check == Check::Satellites || check == Check::Battery;
}

// The range a minimum may take, so that a typo ("minimum": 800 for a battery) is refused, not obeyed.
std::pair<double, double> minimumRange(Check check)
{
    switch (check) {
    case Check::GpsFix: return {1, 5};
    case Check::Satellites: return {1, 64};
    case Check::Battery: return {1, 100};
    default: return {0, 0};
    }
}

unsigned gatesOf(const JsonCursor &list)
{
    unsigned gates = 0;
    for (size_t i = 0, n = list.arraySize(); i < n; ++i)
        gates |= 1u << mission::formats::indexOf(kGateNames, list.at(i));
    return gates;
}

ChecklistItem readItem(const JsonCursor &c)
{
    c.requireObject();
    for (const auto &[key, value] : c.value().items())
        if (key != "check" && key != "title" && key != "minimum" && key != "required" && key != "gates")
            c.failAt(key.c_str(), QCoreApplication::translate("Checklist", "unknown key \"%1\"").arg(QString::fromStdString(key)));
    ChecklistItem item;
    if (const auto check = c.find("check"))
        item.check = Check(mission::formats::indexOf(kCheckNames, *check));
    if (item.check == Check::Manual && c.find("check"))
        c.failAt("check", QCoreApplication::translate("Checklist", "an item the operator ticks has no \"check\"; leave it out"));
    item.title = c.stringOr("title", {}).trimmed();
    if (item.check == Check::Manual && item.title.isEmpty())
        c.fail(QCoreApplication::translate("Checklist", "an item to tick needs a \"title\""));
    if (const auto minimum = c.find("minimum")) {
        if (!takesMinimum(item.check))
            c.failAt("minimum", QCoreApplication::translate("Checklist", "\"%1\" takes no minimum").arg(QLatin1String(kCheckNames[int(item.check)])));
        const double value = minimum->number();
        const auto [low, high] = minimumRange(item.check);
        if (value < low || value > high)
            minimum->fail(QCoreApplication::translate("Checklist", "%1 is outside %2..%3").arg(value).arg(low).arg(high));
        item.minimum = value;
    } else if (takesMinimum(item.check)) {
        c.fail(QCoreApplication::translate("Checklist", "\"%1\" needs a \"minimum\"").arg(QLatin1String(kCheckNames[int(item.check)])));
    }
    item.required = c.booleanOr("required", true);
    if (const auto gates = c.find("gates")) {
        item.gates = gatesOf(*gates);
        if (item.gates == 0)
            gates->fail(QCoreApplication::translate("Checklist", "an empty list holds nothing back; say \"required\": false instead"));
    }
    return item;
}
} // namespace

const char *checkName(Check check)
{
    return kCheckNames[int(check)];
}

Checklist defaultChecklist()
{
    const auto item = [](Check check, std::optional<double> minimum, bool required, unsigned gates) {
        return ChecklistItem{check, {}, minimum, required, gates};
    };
    const auto reminder = [](const char *title) {
        return ChecklistItem{Check::Manual, QCoreApplication::translate("Checklist", title), std::nullopt, false, GateArm | GateAuto};
    };
    Checklist list;
    list.name = QCoreApplication::translate("Checklist", "Sortie's default checklist");
    list.items = {
        item(Check::Link, std::nullopt, true, GateArm | GateAuto),
        item(Check::GpsFix, 3, true, GateArm | GateAuto),
        item(Check::Satellites, 8, true, GateArm | GateAuto),
        item(Check::Battery, 60, true, GateArm | GateAuto),
        item(Check::Home, std::nullopt, true, GateArm | GateAuto),
        item(Check::RouteOnBoard, std::nullopt, true, GateAuto),
        item(Check::RouteCheck, std::nullopt, false, GateAuto),
        item(Check::Camera, std::nullopt, false, GateArm | GateAuto),
        reminder(QT_TRANSLATE_NOOP("Checklist", "Propellers fitted and tight")),
        reminder(QT_TRANSLATE_NOOP("Checklist", "Take-off area clear of people")),
        reminder(QT_TRANSLATE_NOOP("Checklist", "Payload and battery secured")),
    };
    return list;
}

mission::Result<Checklist> readChecklist(const QByteArray &json)
{
    auto parsed = mission::formats::parseJson(json);
    if (!parsed)
        return parsed.error();
    try {
        const JsonCursor root(parsed.value());
        root.requireObject();
        Checklist list;
        list.name = root.stringOr("name", {}).trimmed();
        const JsonCursor items = root.at("items");
        const size_t count = items.arraySize();
        if (count == 0)
            items.fail(QCoreApplication::translate("Checklist", "a checklist needs at least one item"));
        for (size_t i = 0; i < count; ++i)
            list.items.push_back(readItem(items.at(i)));
        return list;
    } catch (const JsonPathError &e) {
        return mission::formats::errorAt(e);
    }
}

} // namespace sortie::preflight
