#include "VciVehicleLink.h"

#include "ElevationService.h"
#include "VciFence.h"
#include "VciMissionPlanner.h"
#include "VciPhoto.h"
#include "Route.h"
#include "VciProfile.h"
#include "VciTelemetryMapper.h"

#include <QDateTime>
#include <QRegularExpression>
#include <QTimer>
#include <QCoreApplication>

namespace sortie::vehicle {
namespace {

namespace profile = vci::profile;
using nlohmann::json;

QString q(std::string_view s)
{
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

QVariant toVariant(const json &value)
{
    if (value.is_boolean())
        return value.get<bool>();
    if (value.is_number())
        return value.get<double>();
    if (value.is_string())
        return QString::fromStdString(value.get<std::string>());
    return {};
}

json toJson(const QVariant &value)
{
    switch (value.typeId()) {
    case QMetaType::Bool: return value.toBool();
    case QMetaType::QString: return value.toString().toStdString();
    default: return value.toDouble();
    }
}

profile::Waypoint toWaypoint(const MissionItem &item)
{
    profile::Waypoint w{radiansFromDegrees(item.latitude), radiansFromDegrees(item.longitude), item.altitude, item.speed, item.acceptanceRadius, {}};
    for (const MissionAction &a : item.actions) {
        json fields = json::object();
        for (auto it = a.parameters.begin(); it != a.parameters.end(); ++it)
            fields[it.key().toStdString()] = toJson(it.value());
        w.actions.push_back({a.type.toStdString(), std::move(fields)});
    }
    return w;
}

MissionItem toItem(const profile::Waypoint &w)
{
    MissionItem item{degreesFromRadians(w.latitude), degreesFromRadians(w.longitude), w.altitude, w.speed, w.acceptanceRadius, {}};
    for (const profile::Action &a : w.actions) {
        MissionAction action{QString::fromStdString(a.type), {}};
        for (const auto &[name, value] : a.fields.items())
            action.parameters.insert(QString::fromStdString(name), toVariant(value));
        item.actions.push_back(std::move(action));
    }
    return item;
}

// The fence that goes up with a prepared mission (the link's own part of it).
struct VciNativeMission : NativeMission
{
    profile::Fence fence;
};

mission::GeoBox boxOf(const std::vector<MissionItem> &items)
{
    mission::GeoBox box;
    for (const MissionItem &i : items) {
        if (box.empty)
            box = {i.latitude, i.longitude, i.latitude, i.longitude, false};
        box.south = std::min(box.south, i.latitude);
        box.north = std::max(box.north, i.latitude);
        box.west = std::min(box.west, i.longitude);
        box.east = std::max(box.east, i.longitude);
    }
    return box;
}

// The fence without a builder: none, which is right only when nothing asks for one.
mission::Result<VciFencePlan> unbuiltFence(const mission::Route &route, const FenceSettings &settings)
{
    if (!route.fence.polygons.empty() || !route.fence.circles.empty() || settings.zones)
        return mission::MissionError{QCoreApplication::translate("VciVehicleLink", "the fence cannot be made: this link was given no fence builder"), {}, 0, 0, {}};
    VciFencePlan plan;
    plan.fence.breachAction = profileBreachAction(settings.breachAction);
    return plan;
}

QString stringField(const json &body, const char *key)
{
    const auto it = body.find(key);
    return it != body.end() && it->is_string() ? QString::fromStdString(it->get<std::string>()) : QString();
}

} // namespace

VciVehicleLink::VciVehicleLink(const vci::VciEndpoint &endpoint, terrain::ElevationService *elevation, QObject *parent)
    : VehicleLink(parent)
    , m_endpoint(endpoint)
    , m_elevation(elevation)
    , m_transport(endpoint)
{
    m_identity.id = endpoint.toString();
    m_identity.name = endpoint.kind == vci::VciEndpoint::Kind::Tcp ? QStringLiteral("%1:%2").arg(endpoint.host).arg(endpoint.port)
                                                                    : endpoint.device;
    m_identity.protocol = protocol();
    connect(&m_transport, &vci::VciTransport::opened, this, [this](QIODevice *device) { m_connection.setDevice(device); });
    connect(&m_transport, &vci::VciTransport::lost, this, [this](const QString &why) {
        m_connection.setDevice(nullptr, why);
        if (!m_stopping)
            setState(State::Lost); // the transport is already trying again
    });
    connect(&m_transport, &vci::VciTransport::attemptFailed, this, &VehicleLink::errorOccurred);
    connect(&m_transport, &vci::VciTransport::certificateAccepted, this, [this](const tls::TlsVerdict &verdict) {
        if (verdict.firstUse()) // trust on first use: the operator sees what was trusted, once
            emit errorOccurred(QCoreApplication::translate("VciVehicleLink", "%1: first secure connection; its certificate is now trusted and remembered. Compare its SHA-256 fingerprint with the vehicle's: %2")
                                   .arg(m_identity.name, verdict.fingerprint));
    });
    connect(&m_transport, &vci::VciTransport::lost, this, [this](const QString &why) {
        if (!m_stopping)
            emit errorOccurred(QCoreApplication::translate("VciVehicleLink", "connection to %1 lost: %2").arg(m_identity.name, why));
    });
    connect(&m_connection, &vci::VciConnection::protocolError, this, &VehicleLink::errorOccurred);
    connect(&m_connection, &vci::VciConnection::attached, this, &VciVehicleLink::onAttached);
    connect(&m_connection, &vci::VciConnection::notified, this, &VciVehicleLink::onNotified);
}

VciVehicleLink::~VciVehicleLink()
{
    m_connection.setDevice(nullptr);
}

void VciVehicleLink::setState(State state)
{
    if (state == m_state)
        return;
    m_state = state;
    emit stateChanged(state);
}

void VciVehicleLink::start()
{
    if (m_state != State::Disconnected)
        return;
    // Remembered now, sent by the connection on every attach, the first one included.
    for (std::string_view uri : profile::kTelemetry)
        m_connection.subscribe(q(uri));
    for (std::string_view uri : profile::kState)
        m_connection.subscribe(q(uri));
    setState(State::Connecting);
    m_transport.open();
}

void VciVehicleLink::stop()
{
    m_stopping = true;
    m_transport.close();
    m_stopping = false;
    m_connection.setDevice(nullptr, QCoreApplication::translate("VciVehicleLink", "disconnected by the operator"));
    m_connection.unsubscribe(QStringLiteral("*")); // forgets them; there is no line to send it on
    setState(State::Disconnected);
}

void VciVehicleLink::onAttached()
{
    setState(State::Connected);
    m_connection.get(q(profile::kVehicle), this, [this](const vci::VciResult &r) {
        if (!r.ok() || !r.body.is_object())
            return;
        VehicleIdentity id = m_identity;
        const QString vehicleId = stringField(r.body, "id");
        if (!vehicleId.isEmpty())
            id.id = vehicleId;
        const QString name = stringField(r.body, "name");
        if (!name.isEmpty())
            id.name = name;
        id.type = stringField(r.body, "type");
        id.autopilot = stringField(r.body, "autopilot");
        if (id == m_identity)
            return;
        m_identity = id;
        emit identityChanged(m_identity);
    });
}

void VciVehicleLink::onNotified(const QString &uri, const nlohmann::json &body)
{
    const std::string u = uri.toStdString();
    if (u == profile::kMission || u == profile::kFence) {
        emit missionChanged();
        return;
    }
    if (u == profile::kFenceStatus)
        onFenceStatus(body);
    if (u == profile::kCameraPhoto) {
        onPhoto(body);
        return;
    }
    TelemetryBatch batch = vciTelemetry(u, body, QDateTime::currentMSecsSinceEpoch());
    if (!batch.empty())
        emit telemetryReceived(batch);
}

CommandResult VciVehicleLink::toCommandResult(const vci::VciResult &result)
{
    return result.ok() ? CommandResult::success() : CommandResult::failure(result.message);
}

void VciVehicleLink::put(std::string_view uri, const json &body, Done done)
{
    m_connection.put(q(uri), body, this, [done = std::move(done)](const vci::VciResult &r) {
        if (done)
            done(toCommandResult(r));
    });
}

void VciVehicleLink::arm(bool armed, Done done)
{
    put(profile::kArmed, armed, std::move(done));
}

void VciVehicleLink::setMode(FlightMode mode, Done done)
{
    put(profile::kMode, std::string(modeName(mode)), std::move(done));
}

void VciVehicleLink::takeoff(double altitude, Done done)
{
    put(profile::kTakeoff, json{{"altitude", altitude}}, std::move(done));
}

void VciVehicleLink::land(Done done)
{
    put(profile::kLand, json::object(), std::move(done));
}

void VciVehicleLink::returnHome(Done done)
{
    put(profile::kReturnHome, json::object(), std::move(done));
}

void VciVehicleLink::goTo(double latitude, double longitude, double altitude, double speed, Done done)
{
    // The profile speaks radians.
    put(profile::kGoto, json{{"latitude", radiansFromDegrees(latitude)}, {"longitude", radiansFromDegrees(longitude)}, {"altitude", altitude}, {"speed", speed}}, std::move(done));
}

void VciVehicleLink::onFenceStatus(const nlohmann::json &body)
{
    const auto status = profile::decodeFenceStatus(body);
    if (!status)
        return;
    // A breach that began since the last status (or one already on when first heard of).
    const bool breached = status->state == "breached";
    const bool began = m_fenceBreaches < 0 ? breached : status->breaches > m_fenceBreaches;
    m_fenceBreaches = status->breaches;
    if (!began)
        return;
    const QString where = status->kind == "outside-inclusion" ? QCoreApplication::translate("VciVehicleLink", "left its fence '%1'")
                                                               : QCoreApplication::translate("VciVehicleLink", "entered the exclusion zone '%1'");
    // What the vehicle does about it: the second part of "fence breach: %1; %2".
    QString action;
    if (status->action == "land")
        //: What a vehicle does after a fence breach: "fence breach: left its fence 'A'; landing".
        action = QCoreApplication::translate("VciVehicleLink", "landing");
    else if (status->action == "hold")
        //: What a vehicle does after a fence breach: "fence breach: left its fence 'A'; holding".
        action = QCoreApplication::translate("VciVehicleLink", "holding");
    else if (status->action == "return")
        //: What a vehicle does after a fence breach: "fence breach: left its fence 'A'; returning home".
        action = QCoreApplication::translate("VciVehicleLink", "returning home");
    else
        //: After a fence breach, the vehicle named no action: "fence breach: left its fence 'A'; action unknown".
        action = QCoreApplication::translate("VciVehicleLink", "action unknown");
    emit alertReported(QCoreApplication::translate("VciVehicleLink", "fence breach: %1; %2").arg(where.arg(QString::fromStdString(status->name)), action));
}

void VciVehicleLink::onPhoto(const nlohmann::json &body)
{
    std::string error;
    const auto photo = profile::decodePhoto(body, &error);
    if (!photo) {
        if (!error.empty())
            emit errorOccurred(QCoreApplication::translate("VciVehicleLink", "a photo report was not understood: %1").arg(QString::fromStdString(error)));
        else
            m_photoSequence = 0;  // null: none taken yet, so the first one is new
        return;
    }
    // The first report after subscribing is the last photo taken before: known, not new. After
    // that, each later sequence is a new photo; a lower one, a vehicle that started counting again.
    const bool known = m_photoSequence < 0 || photo->sequence == m_photoSequence;
    m_photoSequence = photo->sequence;
    if (known)
        return;
    const auto degrees = [](const std::optional<double> &radians) { return radians ? degreesFromRadians(*radians) : qQNaN(); };
    CameraPhoto p;
    p.sequence = photo->sequence;
    p.time = photo->time;
    p.latitude = degreesFromRadians(photo->latitude);
    p.longitude = degreesFromRadians(photo->longitude);
    p.altitudeAmsl = photo->altitudeAmsl.value_or(qQNaN());
    p.altitudeAgl = photo->altitudeAgl.value_or(qQNaN());
    p.roll = degrees(photo->roll);
    p.pitch = degrees(photo->pitch);
    p.yaw = degrees(photo->yaw);
    p.gimbalTilt = degrees(photo->gimbalTilt);
    emit photoTaken(p);
}

void VciVehicleLink::prepareMission(const mission::Route &route, PrepareDone done)
{
    prepareMissionWithFence(route, {}, std::move(done));
}

void VciVehicleLink::prepareMissionWithFence(const mission::Route &route, const FenceSettings &fence, PrepareDone done)
{
    // Heights go up as heights above the vehicle's home: ask it where that is, then plan.
    m_connection.get(q(profile::kHome), this, [this, route, fence, done](const vci::VciResult &result) {
        std::optional<double> homeAmsl;
        if (result.ok() && result.body.is_object())
            if (const auto it = result.body.find("altitudeAmsl"); it != result.body.end() && it->is_number())
                homeAmsl = it->get<double>();
        planMission(route, fence, homeAmsl, done, QDeadlineTimer(kTerrainWaitMs));
    });
}

void VciVehicleLink::planMission(const mission::Route &route, const FenceSettings &fence, std::optional<double> homeAmsl, PrepareDone done,
                                 QDeadlineTimer deadline)
{
    auto mission = vciMissionFor(route, {m_elevation.data(), homeAmsl});
    if (mission && !mission->waitingFor.isEmpty() && m_elevation) {
        if (deadline.hasExpired()) {
            if (done)
                done(CommandResult::failure(QCoreApplication::translate("VciVehicleLink", "the ground under the route did not arrive from %1 in %2 s")
                                                .arg(mission->waitingFor)
                                                .arg(kTerrainWaitMs / 1000)),
                     {});
            return;
        }
        // Plan again once a source has more of the ground (or when the wait is over).
        auto *waiting = new QObject(this);
        auto again = [this, waiting, route, fence, homeAmsl, done, deadline] {
            if (waiting->property("done").toBool())
                return;
            waiting->setProperty("done", true);
            waiting->deleteLater();
            planMission(route, fence, homeAmsl, done, deadline);
        };
        connect(m_elevation, &terrain::ElevationService::changed, waiting, again, Qt::QueuedConnection);
        QTimer::singleShot(std::max<qint64>(0, deadline.remainingTime()), waiting, again);
        return;
    }
    if (!done)
        return;
    if (!mission)
        return done(CommandResult::failure(mission.error().message), {});
    GroundLookup ground;
    if (m_elevation)
        ground = [service = m_elevation](const mission::GeoPoint &p) { return service ? service->groundAt(p) : std::nullopt; };
    auto plan = m_fenceBuilder ? m_fenceBuilder(route, fence, boxOf(mission->items), ground) : unbuiltFence(route, fence);
    if (!plan)
        return done(CommandResult::failure(plan.error().message), {});
    auto native = std::make_shared<VciNativeMission>();
    native->fence = std::move(plan->fence);
    QStringList notices = std::move(mission->notices);
    notices += plan->notices;
    done(CommandResult::success(), PreparedMission{std::move(mission->items), std::move(notices), std::move(native)});
}

void VciVehicleLink::sendFence(const PreparedMission &mission, Done next)
{
    const auto *native = dynamic_cast<const VciNativeMission *>(mission.native.get());
    if (!native)
        return next(CommandResult::success()); // prepared elsewhere: no fence to send
    const profile::Fence fence = native->fence;
    m_connection.put(q(profile::kFence), profile::encodeFence(fence), this, [this, fence, next](const vci::VciResult &r) {
        if (!r.ok()) {
            // A vehicle without the resource can still take a route that needs no fence.
            if (r.statusCode == 501 && fence.empty())
                return next(CommandResult::success());
            return next(CommandResult::failure(QCoreApplication::translate("VciVehicleLink", "the vehicle refused the fence: %1").arg(r.message)));
        }
        // Read back, as the mission is: only the fence the vehicle holds counts.
        m_connection.get(q(profile::kFence), this, [fence, next](const vci::VciResult &held) {
            if (!held.ok())
                return next(CommandResult::failure(QCoreApplication::translate("VciVehicleLink", "the fence could not be read back: %1").arg(held.message)));
            std::string error;
            const auto back = profile::decodeFence(held.body, &error);
            if (!back)
                return next(CommandResult::failure(QCoreApplication::translate("VciVehicleLink", "the vehicle's fence cannot be read: %1").arg(QString::fromStdString(error))));
            if (!(*back == fence))
                return next(CommandResult::failure(QCoreApplication::translate("VciVehicleLink", "the vehicle holds another fence than the one sent (%1 items sent, %2 held)")
                                                       .arg(fence.items.size())
                                                       .arg(back->items.size())));
            next(CommandResult::success());
        });
    });
}

void VciVehicleLink::uploadMission(const PreparedMission &mission, UploadObserver observer, Done done)
{
    // VCI has no locks: the one step is the PUT.
    // The fence first: a mission never flies without the fence it was sent with.
    QMetaObject::invokeMethod(this, [this, mission, observer, done] {
        if (observer.proceed && !observer.proceed()) {
            if (done)
                done(CommandResult::cancel());
            return;
        }
        if (observer.step)
            observer.step(UploadStep::Sending, 0, 0);
        sendFence(mission, [this, items = mission.items, done](const CommandResult &fenced) {
            if (!fenced.ok) {
                if (done)
                    done(fenced);
                return;
            }
            std::vector<profile::Waypoint> waypoints;
            waypoints.reserve(items.size());
            for (const MissionItem &i : items)
                waypoints.push_back(toWaypoint(i));
            put(profile::kMission, profile::encodeMission(waypoints), done);
        });
    }, Qt::QueuedConnection);
}

void VciVehicleLink::downloadMission(MissionDone done)
{
    m_connection.get(q(profile::kMission), this, [done = std::move(done)](const vci::VciResult &r) {
        std::vector<MissionItem> items;
        if (!r.ok()) {
            done(toCommandResult(r), items);
            return;
        }
        std::string error;
        const auto waypoints = profile::decodeMission(r.body, &error);
        if (!waypoints) {
            done(CommandResult::failure(QCoreApplication::translate("VciVehicleLink", "the vehicle's mission cannot be read: %1").arg(QString::fromStdString(error))), items);
            return;
        }
        for (const auto &w : *waypoints)
            items.push_back(toItem(w));
        done(CommandResult::success(), items);
    });
}

void VciVehicleLink::readParameters(ParametersDone done)
{
    m_connection.get(q(profile::kParameters), this, [done = std::move(done)](const vci::VciResult &r) {
        QVariantMap values;
        if (r.ok() && r.body.is_object()) {
            for (const auto &[name, value] : r.body.items()) {
                if (value.is_number())
                    values.insert(QString::fromStdString(name), value.get<double>());
                else if (value.is_string())
                    values.insert(QString::fromStdString(name), QString::fromStdString(value.get<std::string>()));
                else if (value.is_boolean())
                    values.insert(QString::fromStdString(name), value.get<bool>());
            }
        }
        done(r.ok() ? CommandResult::success() : toCommandResult(r), values);
    });
}

void VciVehicleLink::setParameter(const QString &name, double value, Done done)
{
    static const QRegularExpression valid(QStringLiteral("^[A-Za-z0-9_.-]+$"));
    if (!valid.match(name).hasMatch()) {
        QMetaObject::invokeMethod(this, [done, name] {
            if (done)
                done(CommandResult::failure(QCoreApplication::translate("VciVehicleLink", "\"%1\" is not a parameter name").arg(name)));
        }, Qt::QueuedConnection);
        return;
    }
    put(std::string(profile::kParameterPrefix) + name.toStdString(), value, std::move(done));
}

} // namespace sortie::vehicle
