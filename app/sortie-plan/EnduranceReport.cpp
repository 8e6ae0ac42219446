#include "EnduranceReport.h"

#include "RouteValidator.h"


#include <cmath>

namespace sortie::plan {

using mission::formats::Json;
using namespace sortie::endurance;

namespace {
Json number(double v, double scale = 1000.0)
{
    return std::isfinite(v) ? Json(std::round(v * scale) / scale) : Json(nullptr);
}

Json placeJson(const RoutePlace &at)
{
    return {{"leg", at.leg},
            {"distance", number(at.distance)},
            {"latitude", number(at.position.latitude, 1e8)},
            {"longitude", number(at.position.longitude, 1e8)},
            {"altitude", number(at.altitude)},
            {"waypoint", at.segment >= 0 ? Json(at.segment + 1) : Json(nullptr)}};
}

QString clock(double seconds)
{
    const qint64 s = qRound64(seconds);
    return QStringLiteral("%1:%2:%3").arg(s / 3600).arg((s / 60) % 60, 2, 10, QLatin1Char('0')).arg(s % 60, 2, 10, QLatin1Char('0'));
}

QString percent(double fraction)
{
    return QStringLiteral("%1 %").arg(std::round(fraction * 100));
}
} // namespace

std::optional<EnduranceInput> readEnduranceInput(const QString &vehicleFile, const QString &wind, const QString &turns, QString *error)
{
    EnduranceInput input;
    const mission::Result<EnergyProfile> profile = loadEnergyProfile(vehicleFile);
    if (!profile) {
        *error = profile.error().toString();
        return std::nullopt;
    }
    input.profile = *profile;
    if (!wind.isEmpty()) {
        const QStringList parts = wind.split(QLatin1Char(','));
        bool speedOk = false, fromOk = false;
        if (parts.size() == 2) {
            input.conditions.wind.speed = parts[0].toDouble(&speedOk);
            input.conditions.wind.fromDeg = parts[1].toDouble(&fromOk);
        }
        if (!speedOk || !fromOk || !(input.conditions.wind.speed >= 0) || !std::isfinite(input.conditions.wind.fromDeg)) {
            *error = QStringLiteral("--wind needs SPEED,FROM_DEG (m/s, and degrees the wind blows from)");
            return std::nullopt;
        }
    }
    if (turns == QLatin1String("stop"))
        input.conditions.turns = mission::TurnMode::StopAndTurn;
    else if (!turns.isEmpty() && turns != QLatin1String("coordinated")) {
        *error = QStringLiteral("--turns is coordinated or stop");
        return std::nullopt;
    }
    return input;
}

Json enduranceJson(const EnduranceInput &input, const EnduranceEstimate &e)
{
    Json legs = Json::array();
    for (const LegEnergy &l : e.legs) {
        Json leg{{"leg", l.leg}, {"time", number(l.seconds)}, {"energyWh", number(l.energyWh)}};
        if (l.returnHome)
            leg["returnHome"] = true;
        legs.push_back(std::move(leg));
    }
    Json changes = Json::array();
    for (const BatteryChange &c : e.changes) {
        Json change = placeJson(c.at);
        change["planned"] = c.planned;
        change["batteryLeft"] = number(c.batteryLeft);
        changes.push_back(std::move(change));
    }
    Json pnr = nullptr;
    if (e.pointOfNoReturn)
        pnr = placeJson(*e.pointOfNoReturn);
    const EnergyProfile &p = input.profile;
    return {{"flightTime", number(e.flightTimeSeconds)},
            {"energyWh", number(e.energyWh)},
            {"batteryAtEnd", number(e.batteryAtEnd)},
            {"batteriesNeeded", e.batteriesNeeded},
            {"pointOfNoReturn", pnr},
            {"legs", legs},
            {"batteryChanges", changes},
            {"lastBatteryAtEnd", number(e.lastBatteryAtEnd)},
            {"homeKnown", e.homeKnown},
            {"legTooLong", e.legTooLong > 0 ? Json(e.legTooLong) : Json(nullptr)},
            {"profile", {{"name", p.name.toStdString()}, {"source", sourceName(p.source).toStdString()}, {"batteryWh", p.batteryWh},
                         {"reserve", p.reserve}, {"usableWh", number(p.usableWh())}}},
            {"wind", {{"speed", input.conditions.wind.speed}, {"from", input.conditions.wind.fromDeg}}},
            {"turns", input.conditions.turns == mission::TurnMode::StopAndTurn ? "stop" : "coordinated"}};
}

void printEndurance(QTextStream &out, const mission::Route &route, const EnduranceInput &input, const EnduranceEstimate &e)
{
    const EnergyProfile &p = input.profile;
    out << "  endurance with \"" << p.name << "\" (" << sourceName(p.source) << "): " << clock(e.flightTimeSeconds) << ", "
        << QString::number(e.energyWh, 'f', 1) << " Wh of " << QString::number(p.batteryWh, 'f', 1) << " Wh, battery at end "
        << percent(e.batteryAtEnd) << " (reserve " << percent(p.reserve) << "), " << e.batteriesNeeded
        << (e.batteriesNeeded == 1 ? " battery" : " batteries") << "\n";
    if (input.conditions.wind.speed > 0)
        out << "    wind " << input.conditions.wind.speed << " m/s from " << input.conditions.wind.fromDeg << "°\n";
    for (const BatteryChange &c : e.changes)
        out << "    change the battery at " << (c.at.segment >= 0 ? mission::segmentLabel(route, c.at.segment) : QStringLiteral("home"))
            << " (leg " << c.at.leg << ", " << QString::number(c.at.distance, 'f', 1) << " m), " << percent(c.batteryLeft) << " left"
            << (c.planned ? ", a planned landing" : ", no landing planned") << "\n";
    if (e.legTooLong)
        out << "    leg " << e.legTooLong << " alone needs more than one battery\n";
    if (e.pointOfNoReturn)
        out << "    point of no return: leg " << e.pointOfNoReturn->leg << " at " << QString::number(e.pointOfNoReturn->distance, 'f', 1)
            << " m\n";
    else
        out << "    point of no return: " << (e.homeKnown ? "none (home stays in reach)" : "unknown (no home)") << "\n";
}

} // namespace sortie::plan
