#include "TelemetryFieldNames.h"

#include <QCoreApplication>

#include <array>

namespace sortie::ui {

namespace {
using vehicle::TelemetryField;
// In TelemetryField's order; translated where shown, so a language change re-words them.
constexpr std::array<const char *, vehicle::kTelemetryFieldCount> kTitles{
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Latitude"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Longitude"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Altitude (AMSL)"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Altitude above home"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Roll"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Pitch"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Heading"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Course"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Ground speed"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Air speed"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Vertical speed"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Battery voltage"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Battery current"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Battery remaining"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "GPS fix"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Satellites"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "HDOP"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Home latitude"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Home longitude"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Home altitude (AMSL)"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Armed"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Flight mode"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Mission state"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Current waypoint"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Waypoints reached"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Waypoints on board"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Fence breached"),
    QT_TRANSLATE_NOOP("TelemetryFieldNames", "Fence breaches"),
};
} // namespace

QString telemetryFieldTitle(vehicle::TelemetryField field)
{
    const auto i = size_t(field);
    return i < kTitles.size() ? QCoreApplication::translate("TelemetryFieldNames", kTitles[i]) : QString();
}

} // namespace sortie::ui
