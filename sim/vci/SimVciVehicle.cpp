#include "SimVciVehicle.h"

#include "SimTerrain.h"

#include "VciPhoto.h"
#include "VciProfile.h"

#include <QDateTime>

#include <algorithm>
#include <cmath>

namespace sortie::sim {
namespace {

namespace profile = vci::profile;
using nlohmann::json;

constexpr double kRad = 3.14159265358979323846 / 180.0;
constexpr int kTickMs = 20;
constexpr double kMaxStepSeconds = 0.1;

bool is(const std::string &uri, std::string_view name) { return uri == name; }

} // namespace

SimVciVehicle::SimVciVehicle(const SimVciOptions &options, QObject *parent)
    : QObject(parent)
    , m_options(options)
    , m_model(options.homeLatitude, options.homeLongitude,
              options.terrain ? options.terrain->groundOr(options.homeLatitude, options.homeLongitude, options.groundElevation)
                              : options.groundElevation,
              FlightModel::Limits::forProfile(options.energy))
    , m_startMs(QDateTime::currentMSecsSinceEpoch())
{
    if (options.terrain)
        m_model.setGround([terrain = options.terrain](double lat, double lon) { return terrain->groundAt(lat, lon); });
    m_model.setWaypointReached([this](int index) { runCameraActions(index); });
    m_parameters["telemetry_rate"] = options.telemetryRate;
    m_parameters["takeoff_altitude"] = m_model.limits().takeoffAltitude;
    m_parameters["mission_speed"] = m_model.limits().cruiseSpeed;
    m_clock.start();
    m_tick.setTimerType(Qt::PreciseTimer);
    connect(&m_tick, &QTimer::timeout, this, &SimVciVehicle::tick);
    m_tick.start(kTickMs);
    for (std::string_view uri : profile::kState)
        if (uri != profile::kFence) // announced when PUT, not compared every tick (it may be large)
            m_lastState[std::string(uri)] = *resource(std::string(uri));
}

void SimVciVehicle::tick()
{
    // In steps of at most kMaxStepSeconds of simulated time, however late the timer fired and fast
    // the clock runs, so a busy machine flies the same path and takes its photos where they fall.
    const double dt = double(m_clock.restart()) / 1000.0 * m_options.timeScale;
    const int steps = std::max(1, int(std::ceil(dt / kMaxStepSeconds)));
    for (int i = 0; i < steps; ++i) {
        m_simulatedSeconds += dt / steps;
        m_model.tick(dt / steps);
        const size_t photos = m_shutter.photos().size();
        m_shutter.tick(m_model.state(), shutterClock());
        if (m_shutter.photos().size() != photos && i + 1 < steps)
            checkChanges(); // each photo is notified, not only the tick's last
    }
    enforceFence();
    checkChanges();
}

void SimVciVehicle::checkChanges()
{
    for (auto &[uri, last] : m_lastState) {
        json current = *resource(uri);
        if (current != last) {
            last = std::move(current);
            emit changed(QString::fromStdString(uri));
        }
    }
}

int64_t SimVciVehicle::now() const
{
    if (m_options.simulatedClock)
        return m_startMs + int64_t(std::llround(m_simulatedSeconds * 1000.0));
    return QDateTime::currentMSecsSinceEpoch();
}

bool SimVciVehicle::isPeriodic(const std::string &uri) const
{
    for (std::string_view t : profile::kTelemetry) {
        if (uri == t)
            return true;
    }
    return false;
}

bool SimVciVehicle::isSubscribable(const std::string &uri) const
{
    if (isPeriodic(uri))
        return true;
    for (std::string_view s : profile::kState) {
        if (uri == s)
            return true;
    }
    return uri.rfind(profile::kParameterPrefix, 0) == 0 && resource(uri).has_value();
}

json SimVciVehicle::progress() const
{
    const auto &s = m_model.state();
    const int count = int(m_model.mission().size());
    std::string state = "idle";
    int reached = 0;
    if (count > 0 && s.missionComplete) {
        state = "complete";
        reached = count;
    } else if (count > 0 && s.mode == FlightModel::Mode::Auto) {
        state = "active";
        reached = std::max(0, s.currentWaypoint);
    } else if (count > 0 && s.currentWaypoint >= 0) {
        state = "paused";
        reached = s.currentWaypoint;
    }
    return {{"state", state}, {"current", s.missionComplete ? -1 : s.currentWaypoint}, {"reached", reached}, {"count", count}};
}

json SimVciVehicle::parameters() const
{
    const auto &l = m_model.limits();
    json p = {{"cruise_speed", l.cruiseSpeed}, {"max_speed", l.maxSpeed}, {"climb_rate", l.climbRate},
              {"descent_rate", l.descentRate}, {"acceptance_radius", l.acceptanceRadius}, {"return_altitude", l.returnAltitude}};
    for (const auto &[name, value] : m_parameters)
        p[name] = value;
    return p;
}

std::optional<json> SimVciVehicle::resource(const std::string &uri) const
{
    const auto &s = m_model.state();
    if (is(uri, profile::kVehicle))
        return json{{"id", m_options.id.toStdString()}, {"name", m_options.name.toStdString()}, {"type", "multicopter"},
                    {"autopilot", "sortie-sim"}, {"firmware", "1.0"}, {"profile", "sortie-vci/1"}};
    if (is(uri, profile::kPosition)) {
        // The model flies above its home ground; the height above the ground below is what is reported.
        const double amsl = s.altitudeAmsl();
        const double agl = m_options.terrain ? amsl - m_options.terrain->groundOr(s.latitude, s.longitude, s.groundElevation) : s.altitudeAgl;
        return json{{"latitude", s.latitude * kRad}, {"longitude", s.longitude * kRad}, {"altitudeAmsl", amsl},
                    {"altitudeAgl", agl}, {"time", now()}};
    }
    if (is(uri, profile::kAttitude))
        return json{{"roll", s.roll * kRad}, {"pitch", s.pitch * kRad}, {"yaw", s.heading * kRad}, {"time", now()}};
    if (is(uri, profile::kSpeed))
        return json{{"ground", s.groundSpeed}, {"air", s.groundSpeed}, {"vertical", s.verticalSpeed},
                    {"course", s.heading * kRad}, {"time", now()}};
    if (is(uri, profile::kBattery)) {
        return json{{"voltage", s.batteryVoltage}, {"current", s.batteryCurrent}, {"remaining", s.batteryRemaining}, {"time", now()}};
    }
    if (is(uri, profile::kGps))
        return json{{"fix", s.gpsFix}, {"satellites", s.satellites}, {"hdop", 0.8}, {"time", now()}};
    if (is(uri, profile::kHome))
        return json{{"latitude", s.homeLatitude * kRad}, {"longitude", s.homeLongitude * kRad},
                    {"altitudeAmsl", s.groundElevation}, {"time", now()}};
    if (is(uri, profile::kArmed))
        return json(s.armed);
    if (is(uri, profile::kMode))
        return json(FlightModel::modeName(s.mode));
    if (is(uri, profile::kMission)) {
        // What was accepted, as it was sent, with the speeds the vehicle filled in.
        std::vector<vci::profile::Waypoint> list = m_missionAsSent;
        for (size_t i = 0; i < list.size() && i < m_model.mission().size(); ++i)
            list[i].speed = m_model.mission()[i].speed;
        json m = profile::encodeMission(list);
        m["version"] = m_model.missionVersion();
        return m;
    }
    if (is(uri, profile::kMissionProgress))
        return progress();
    if (is(uri, profile::kFence)) {
        json f = profile::encodeFence(m_fence.fence());
        f["version"] = m_fence.version();
        return f;
    }
    if (is(uri, profile::kFenceStatus))
        return profile::encodeFenceStatus(m_fence.status(now()));
    if (is(uri, profile::kCameraPhoto)) {
        if (m_shutter.photos().empty())
            return json(nullptr);
        const SimPhoto &p = m_shutter.photos().back();
        vci::profile::Photo photo{p.sequence, p.time, p.latitude * kRad, p.longitude * kRad};
        photo.altitudeAmsl = p.altitudeAmsl;
        photo.altitudeAgl = p.altitudeAgl;
        photo.roll = p.roll * kRad;
        photo.pitch = p.pitch * kRad;
        photo.yaw = p.heading * kRad;
        photo.gimbalTilt = p.gimbalTilt * kRad;
        return vci::profile::encodePhoto(photo);
    }
    if (is(uri, profile::kParameters))
        return parameters();
    if (uri.rfind(profile::kParameterPrefix, 0) == 0) {
        const json all = parameters();
        const auto it = all.find(uri.substr(profile::kParameterPrefix.size()));
        if (it != all.end())
            return *it;
    }
    return std::nullopt;
}

SimVciReply SimVciVehicle::handle(const vci::VciMessage &request)
{
    const std::string &uri = request.uri;
    if (request.verb == vci::VciVerb::Get) {
        if (auto value = resource(uri))
            return SimVciReply::ok(std::move(*value));
        return SimVciReply::error(501, "this vehicle has no resource " + uri);
    }
    if (request.verb == vci::VciVerb::Put) {
        if (request.hasBody && !request.jsonBody)
            return SimVciReply::error(400, "PUT bodies must be JSON");
        SimVciReply reply = put(uri, request);
        checkChanges(); // subscribers hear about it at once, not at the next tick
        return reply;
    }
    return SimVciReply::error(501, "this vehicle does not serve " + std::string(vci::toString(request.verb)));
}

SimVciReply SimVciVehicle::refusedOrOk(const FlightModel::Refusal &refusal, json value)
{
    if (!refusal.empty())
        return SimVciReply::error(400, refusal);
    return SimVciReply::ok(std::move(value));
}

SimVciReply SimVciVehicle::put(const std::string &uri, const vci::VciMessage &request)
{
    const json &body = request.body;
    if (is(uri, profile::kArmed)) {
        if (!body.is_boolean())
            return SimVciReply::error(400, "/state/armed takes true or false");
        return refusedOrOk(body.get<bool>() ? m_model.arm() : m_model.disarm(), body);
    }
    if (is(uri, profile::kMode)) {
        FlightModel::Mode mode;
        if (!body.is_string() || !FlightModel::modeFromName(body.get<std::string>(), &mode))
            return SimVciReply::error(400, "/state/mode takes one of manual, hold, takeoff, auto, guided, land, return_home");
        if (mode == FlightModel::Mode::Auto && (m_model.state().missionComplete || m_model.state().currentWaypoint < 0))
            return refusedOrOk(m_model.startMission(), body); // from the first waypoint again
        if (mode == FlightModel::Mode::Takeoff)
            return refusedOrOk(m_model.takeoff(m_parameters["takeoff_altitude"]), body);
        return refusedOrOk(m_model.setMode(mode), body);
    }
    if (is(uri, profile::kTakeoff)) {
        double altitude = m_parameters["takeoff_altitude"];
        if (body.is_number())
            altitude = body.get<double>();
        else if (auto a = profile::number(body, "altitude"))
            altitude = *a;
        else if (!body.is_null() && !(body.is_object() && body.empty()))
            return SimVciReply::error(400, "/command/takeoff takes {\"altitude\": metres} or nothing");
        if (!(altitude > 0) || altitude > 500)
            return SimVciReply::error(400, "take-off altitude must be between 0 and 500 m");
        return refusedOrOk(m_model.takeoff(altitude), json{{"altitude", altitude}});
    }
    if (is(uri, profile::kLand))
        return refusedOrOk(m_model.land(), nullptr);
    if (is(uri, profile::kReturnHome))
        return refusedOrOk(m_model.returnHome(), nullptr);
    if (is(uri, profile::kGoto)) {
        const auto lat = profile::number(body, "latitude"), lon = profile::number(body, "longitude");
        const auto alt = profile::number(body, "altitude");
        if (!lat || !lon || !alt)
            return SimVciReply::error(400, "/command/goto takes {\"latitude\", \"longitude\" (radians), \"altitude\" (m)}");
        return refusedOrOk(m_model.goTo(*lat / kRad, *lon / kRad, *alt, profile::number(body, "speed").value_or(0)), body);
    }
    if (is(uri, profile::kMission)) {
        std::string error;
        const auto waypoints = profile::decodeMission(body, &error);
        if (!waypoints)
            return SimVciReply::error(400, error);
        std::vector<FlightModel::Waypoint> mission;
        for (const auto &w : *waypoints) {
            FlightModel::Waypoint p{w.latitude / kRad, w.longitude / kRad, w.altitude, w.speed > 0 ? w.speed : m_parameters["mission_speed"]};
            p.acceptanceRadius = w.acceptanceRadius;
            // The simulated vehicle flies waits and landings, and its shutter runs the camera
            // actions (runCameraActions); the other actions are kept (and read back) but change
            // nothing in its flight.
            for (const auto &a : w.actions) {
                if (a.type == "wait")
                    p.holdSeconds += a.fields.value("seconds", 0.0);
                else if (a.type == "land")
                    p.landHere = true;
            }
            mission.push_back(p);
        }
        const FlightModel::Refusal refusal = m_model.setMission(std::move(mission));
        if (refusal.empty())
            m_missionAsSent = *waypoints;
        return refusedOrOk(refusal, *resource(std::string(profile::kMission)));
    }
    if (is(uri, profile::kFence))
        return putFence(body);
    if (uri.rfind(profile::kParameterPrefix, 0) == 0)
        return putParameter(uri.substr(profile::kParameterPrefix.size()), request);
    if (resource(uri))
        return SimVciReply::error(501, uri + " is read-only");
    return SimVciReply::error(501, "this vehicle has no resource " + uri);
}

void SimVciVehicle::runCameraActions(int waypoint)
{
    if (waypoint < 0 || size_t(waypoint) >= m_missionAsSent.size())
        return;
    for (const vci::profile::Action &a : m_missionAsSent[size_t(waypoint)].actions) {
        const auto number = [&a](const char *key, double fallback) { return profile::number(a.fields, key).value_or(fallback); };
        if (a.type == "camera" && a.fields.value("state", std::string()) == "single")
            m_shutter.single(m_model.state(), shutterClock());
        else if (a.type == "camera_by_distance")
            m_shutter.startByDistance(number("interval", 0), int(number("shots", 0)), number("delay", 0), shutterClock());
        else if (a.type == "camera_by_time")
            m_shutter.startByTime(number("interval", 0), int(number("shots", 0)), number("delay", 0), shutterClock());
        else if (a.type == "gimbal" && profile::number(a.fields, "tilt"))
            m_shutter.setGimbalTilt(number("tilt", 0) / kRad);
    }
}

SimVciReply SimVciVehicle::putFence(const json &body)
{
    std::string error;
    auto fence = profile::decodeFence(body, &error);
    if (!fence)
        return SimVciReply::error(400, error);
    if (m_model.state().mode == FlightModel::Mode::Auto)
        return SimVciReply::error(400, "cannot replace the fence while flying the mission; pause first");
    m_fence.set(std::move(*fence));
    emit changed(QString::fromStdString(std::string(profile::kFence)));
    return SimVciReply::ok(*resource(std::string(profile::kFence)));
}

void SimVciVehicle::enforceFence()
{
    const auto action = m_fence.check(m_model.state());
    if (!action || m_model.state().mode == FlightModel::Mode::Land)
        return; // already coming down: nothing is safer
    switch (*action) {
    case profile::BreachAction::Return: m_model.returnHome(); break;
    case profile::BreachAction::Land: m_model.land(); break;
    case profile::BreachAction::Hold: m_model.pause(); break;
    }
}

SimVciReply SimVciVehicle::putParameter(const std::string &name, const vci::VciMessage &request)
{
    const auto it = m_parameters.find(name);
    if (it == m_parameters.end()) {
        if (parameters().contains(name))
            return SimVciReply::error(400, "parameter " + name + " is read-only on this vehicle");
        return SimVciReply::error(501, "this vehicle has no parameter " + name);
    }
    if (!request.body.is_number() || !(request.body.get<double>() > 0))
        return SimVciReply::error(400, "parameter " + name + " takes a number above 0");
    it->second = request.body.get<double>();
    emit changed(QString::fromStdString(std::string(profile::kParameterPrefix) + name));
    return SimVciReply::ok(request.body);
}

} // namespace sortie::sim
