#include "SimCommands.h"

#include "Messages.pb.h"

#include <array>
#include <optional>

namespace sortie::sim {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

using Mode = FlightModel::Mode;

struct Spec
{
    const char *code;
    const char *name;
    bool (*available)(const FlightModel::State &);
};

const std::array kCommands = {
    Spec{"arm", "Arm", [](const FlightModel::State &s) { return !s.armed; }},
    Spec{"disarm", "Disarm", [](const FlightModel::State &s) { return s.armed && !s.airborne(); }},
    Spec{"takeoff_command", "Take off", [](const FlightModel::State &s) { return s.armed && !s.airborne(); }},
    Spec{"auto", "Auto mode", [](const FlightModel::State &s) { return s.armed && s.mode != Mode::Auto; }},
    Spec{"mission_pause", "Pause mission", [](const FlightModel::State &s) { return s.mode == Mode::Auto; }},
    Spec{"mission_resume", "Resume mission",
         [](const FlightModel::State &s) { return s.mode == Mode::Hold && s.currentWaypoint >= 0 && s.armed; }},
    Spec{"land_command", "Land", [](const FlightModel::State &s) { return s.airborne() && s.mode != Mode::Land; }},
    Spec{"return_to_home", "Return to home", [](const FlightModel::State &s) { return s.airborne() && s.mode != Mode::ReturnHome; }},
    Spec{"waypoint", "Go to waypoint", [](const FlightModel::State &s) { return s.armed; }},
    Spec{"manual", "Manual mode", [](const FlightModel::State &) { return true; }},
};

void addArgument(pb::CommandDefinition &d, int id, const char *code, pb::Semantic semantic, bool mandatory,
                 std::optional<double> defaultValue = {}, std::optional<double> min = {}, std::optional<double> max = {})
{
    auto *a = d.add_arguments();
    a->set_id(id);
    a->set_code(code);
    a->set_semantic(semantic);
    a->set_mandatory(mandatory);
    if (defaultValue)
        a->mutable_defaultvalue()->set_doublevalue(*defaultValue);
    if (min)
        a->mutable_minvalue()->set_doublevalue(*min);
    if (max)
        a->mutable_maxvalue()->set_doublevalue(*max);
}

std::optional<double> argument(const pb::Command &command, const char *code)
{
    for (const auto &a : command.arguments()) {
        if (a.code() != code)
            continue;
        const auto &v = a.value();
        if (v.has_doublevalue()) return v.doublevalue();
        if (v.has_floatvalue()) return v.floatvalue();
        if (v.has_intvalue()) return v.intvalue();
        if (v.has_longvalue()) return double(v.longvalue());
    }
    return std::nullopt;
}

SimCommands::Result refusedBy(const FlightModel::Refusal &refusal)
{
    if (refusal.empty())
        return {pb::CS_SUCCEEDED, {}};
    return {pb::CS_FAILED, QStringLiteral("Command rejected by vehicle: ") + QString::fromStdString(refusal)};
}

} // namespace

std::vector<pb::CommandDefinition> SimCommands::definitions(const pb::Vehicle &vehicleRef, const FlightModel &model)
{
    std::vector<pb::CommandDefinition> out;
    const int base = 10000 + vehicleRef.id() * 100;
    for (size_t i = 0; i < kCommands.size(); ++i) {
        pb::CommandDefinition d;
        d.set_id(base + int(i));
        d.set_version(1);
        d.set_code(kCommands[i].code);
        d.set_name(kCommands[i].name);
        d.set_subsystem(pb::S_FLIGHT_CONTROLLER);
        d.set_subsystemid(0);
        *d.mutable_vehicle() = vehicleRef;
        d.set_enabled(true);
        d.set_available(kCommands[i].available(model.state()));
        const int arg = base * 10 + int(i) * 10;
        if (d.code() == "waypoint") {
            addArgument(d, arg + 1, "latitude", pb::S_LATITUDE, true);
            addArgument(d, arg + 2, "longitude", pb::S_LONGITUDE, true);
            addArgument(d, arg + 3, "altitude_agl", pb::S_ALTITUDE_AGL, false);
            addArgument(d, arg + 4, "altitude_amsl", pb::S_ALTITUDE_AMSL, false);
            addArgument(d, arg + 5, "ground_speed", pb::S_GROUND_SPEED, false, 5.0, 0.5, model.limits().maxSpeed);
        } else if (d.code() == "takeoff_command") {
            addArgument(d, arg + 1, "altitude_agl", pb::S_ALTITUDE_AGL, false, model.limits().takeoffAltitude, 2.0, 500.0);
        }
        out.push_back(std::move(d));
    }
    return out;
}

quint32 SimCommands::availability(const FlightModel &model)
{
    quint32 bits = 0;
    for (size_t i = 0; i < kCommands.size(); ++i)
        if (kCommands[i].available(model.state()))
            bits |= 1u << i;
    return bits;
}

SimCommands::Result SimCommands::execute(FlightModel &model, const pb::Command &command)
{
    const std::string &code = command.code();
    if (code == "arm") return refusedBy(model.arm());
    if (code == "disarm") return refusedBy(model.disarm());
    if (code == "takeoff_command") return refusedBy(model.takeoff(argument(command, "altitude_agl").value_or(0)));
    if (code == "auto") {
        const auto &s = model.state();
        return refusedBy(s.currentWaypoint >= 0 && s.mode == Mode::Hold ? model.resume() : model.startMission());
    }
    if (code == "mission_pause") return refusedBy(model.pause());
    if (code == "mission_resume") return refusedBy(model.resume());
    if (code == "land_command") return refusedBy(model.land());
    if (code == "return_to_home") return refusedBy(model.returnHome());
    if (code == "manual") return refusedBy(model.manual());
    if (code == "waypoint") {
        const auto lat = argument(command, "latitude");
        const auto lon = argument(command, "longitude");
        if (!lat || !lon)
            return {pb::CS_REJECTED, QStringLiteral("waypoint needs the arguments latitude and longitude (radians)")};
        const auto &s = model.state();
        double agl = s.altitudeAgl;
        if (const auto a = argument(command, "altitude_agl"))
            agl = *a;
        else if (const auto amsl = argument(command, "altitude_amsl"))
            agl = *amsl - s.groundElevation;
        return refusedBy(model.goTo(*lat * kDeg, *lon * kDeg, agl, argument(command, "ground_speed").value_or(0)));
    }
    return {pb::CS_REJECTED, QStringLiteral("The vehicle has no command '%1'").arg(QString::fromStdString(code))};
}

} // namespace sortie::sim
