#include "HciVehicleLink.h"

#include "HciClient.h"
#include "HciLock.h"
#include "HciRouteMapper.h"
#include "ProcessedPlan.h"
#include "HciReply.h"
#include "HciSession.h"
#include "HciSubscription.h"
#include "HciTelemetryMapper.h"
#include "VehicleLog.h"
#include "Messages.pb.h"

#include <QDateTime>

#include <numbers>
#include <QCoreApplication>

namespace sortie::vehicle {

namespace pb = com::ugcs::ucs::proto;
using hci::HciObjectType;
using hci::HciReply;

HciVehicleLink::HciVehicleLink(hci::HciClient *client, const pb::Vehicle &vehicle, QObject *parent)
    : VehicleLink(parent)
    , m_client(client)
    , m_vehicle(std::make_unique<pb::Vehicle>(vehicle))
    , m_routePass(vehicle.id())
{
    m_identity.id = QString::number(vehicle.id());
    m_identity.name = QString::fromStdString(vehicle.name());
    m_identity.type = QString::fromStdString(pb::VehicleType_Name(vehicle.type()));
    m_identity.autopilot = QString::fromStdString(vehicle.platform().name().empty() ? vehicle.platform().code() : vehicle.platform().name());
    m_identity.protocol = protocol();
    connect(client->session(), &hci::HciSession::stateChanged, this, &HciVehicleLink::updateState);
    connect(client->session(), &hci::HciSession::errorOccurred, this, [this](const hci::HciError &error) {
        if (m_started)
            emit errorOccurred(error.message());
    });
}

HciVehicleLink::~HciVehicleLink()
{
    if (m_subscription)
        m_client->session()->unsubscribe(m_subscription);
    if (m_routePassSubscription)
        m_client->session()->unsubscribe(m_routePassSubscription);
}

int HciVehicleLink::vehicleObjectId() const
{
    return m_vehicle->id();
}

void HciVehicleLink::updateState()
{
    State s = State::Disconnected;
    if (m_started) {
        switch (m_client->session()->state()) {
        case hci::HciSession::State::Ready: s = State::Connected; break;
        case hci::HciSession::State::Reconnecting: s = State::Lost; break;
        case hci::HciSession::State::Disconnected: s = State::Disconnected; break;
        default: s = State::Connecting; break;
        }
    }
    if (s == m_state)
        return;
    m_state = s;
    if (s == State::Connected)
        readRoutePasses(); // what changed while we were away is not replayed
    emit stateChanged(s);
}

void HciVehicleLink::start()
{
    if (m_started)
        return;
    m_started = true;
    m_subscription = m_client->subscribeTelemetry(m_vehicle->id());
    connect(m_subscription, &hci::HciSubscription::received, this, &HciVehicleLink::onEvent);
    m_routePassSubscription = m_client->subscribeObjectChanges(HciObjectType::RoutePass);
    connect(m_routePassSubscription, &hci::HciSubscription::received, this, &HciVehicleLink::onRoutePassEvent);
    updateState();
}

void HciVehicleLink::stop()
{
    m_started = false;
    if (m_subscription)
        m_client->session()->unsubscribe(m_subscription);
    if (m_routePassSubscription)
        m_client->session()->unsubscribe(m_routePassSubscription);
    updateState();
}

void HciVehicleLink::onEvent(const pb::EventWrapper &event)
{
    if (!event.has_telemetryevent() || event.telemetryevent().vehicle().id() != m_vehicle->id())
        return; // the server may send every vehicle's telemetry
    TelemetryBatch batch = hciTelemetry(event.telemetryevent(), QDateTime::currentMSecsSinceEpoch());
    if (!batch.empty())
        emit telemetryReceived(batch);
    if (const auto uri = hciVideoStreamUri(event.telemetryevent()))
        emit videoStreamUriReported(QString::fromStdString(*uri));
}

template<class F>
void HciVehicleLink::onFinished(HciReply *reply, F &&f)
{
    connect(reply, &HciReply::finished, this, [reply, f = std::forward<F>(f)] { f(*reply); });
}

void HciVehicleLink::onRoutePassEvent(const pb::EventWrapper &event)
{
    if (!event.has_objectmodificationevent())
        return;
    m_routePassSeen = true;
    report(m_routePass.apply(event.objectmodificationevent(), QDateTime::currentMSecsSinceEpoch()));
}

void HciVehicleLink::readRoutePasses()
{
    m_routePassSeen = false;
    onFinished(m_client->listObjects(HciObjectType::RoutePass), [this](const HciReply &reply) {
        if (!reply.isOk()) {
            qCDebug(lcVehicle).noquote() << m_identity.name << "RoutePass list not available:" << reply.error().message();
            return;
        }
        if (m_routePassSeen)
            return; // events since the request are newer than the list
        for (const auto &w : reply.response<pb::GetObjectListResponse>().objects())
            if (w.has_routepass() && w.routepass().vehicle().id() == m_vehicle->id())
                report(m_routePass.apply(w.routepass(), QDateTime::currentMSecsSinceEpoch()));
    });
}

void HciVehicleLink::report(const HciRoutePassTracker::Outcome &outcome)
{
    using Kind = HciRoutePassTracker::Outcome::Kind;
    if (outcome.kind == Kind::Dropped) {
        qCWarning(lcVehicle).noquote() << m_identity.name << "dropped a RoutePass event:" << outcome.reason;
        emit errorOccurred(outcome.reason);
    } else if (outcome.kind == Kind::Applied) {
        emit telemetryReceived(outcome.batch);
    }
}

void HciVehicleLink::failLater(Done done, const QString &why)
{
    QMetaObject::invokeMethod(this, [done, why] {
        if (done)
            done(CommandResult::failure(why));
    }, Qt::QueuedConnection);
}

void HciVehicleLink::underLock(const QString &what, Work work, Done done)
{
    hci::underLock<CommandResult>(m_client, HciObjectType::Vehicle, m_vehicle->id(), this, {
        std::move(work),
        [this, what](const hci::HciError &refusal) {
            return CommandResult::failure(QCoreApplication::translate("HciVehicleLink", "%1: cannot take control of %2: %3").arg(what, m_identity.name, refusal.message()));
        },
        [done](CommandResult result) {
            if (done)
                done(result);
        },
        {}, {}});
}

void HciVehicleLink::command(const QString &code, const QVariantMap &arguments, Done done)
{
    const int id = m_vehicle->id();
    underLock(code, [this, id, code, arguments](Done finish) {
        onFinished(m_client->sendCommand(*m_vehicle, code, arguments), [id, code, finish](const HciReply &reply) {
            if (!reply.isOk()) {
                finish(CommandResult::failure(QStringLiteral("%1: %2").arg(code, reply.error().message())));
                return;
            }
            for (const auto &r : reply.response<pb::SendCommandResponse>().commandresults()) {
                if (r.vehicle().id() != id)
                    continue;
                if (r.commandstatus() == pb::CS_SUCCEEDED) {
                    finish(CommandResult::success());
                } else {
                    const QString why = r.has_errormessage() ? QString::fromStdString(r.errormessage())
                                                             : QString::fromStdString(pb::CommandStatus_Name(r.commandstatus()));
                    finish(CommandResult::failure(QStringLiteral("%1: %2").arg(code, why)));
                }
                return;
            }
            finish(CommandResult::failure(QCoreApplication::translate("HciVehicleLink", "%1: the server sent no result for this vehicle").arg(code)));
        });
    }, std::move(done));
}

void HciVehicleLink::arm(bool armed, Done done)
{
    command(armed ? QStringLiteral("arm") : QStringLiteral("disarm"), {}, std::move(done));
}

void HciVehicleLink::setMode(FlightMode mode, Done done)
{
    // UgCS changes modes by commands; these are the flight-controller codes the SDK lists.
    switch (mode) {
    case FlightMode::Manual: command(QStringLiteral("manual"), {}, std::move(done)); return;
    case FlightMode::Auto: command(QStringLiteral("auto"), {}, std::move(done)); return;
    case FlightMode::Hold: command(QStringLiteral("mission_pause"), {}, std::move(done)); return;
    case FlightMode::Guided: command(QStringLiteral("guided"), {}, std::move(done)); return;
    case FlightMode::Takeoff: command(QStringLiteral("takeoff_command"), {}, std::move(done)); return;
    case FlightMode::Land: command(QStringLiteral("land_command"), {}, std::move(done)); return;
    case FlightMode::ReturnHome: command(QStringLiteral("return_to_home"), {}, std::move(done)); return;
    case FlightMode::Unknown: break;
    }
    failLater(std::move(done), QCoreApplication::translate("HciVehicleLink", "there is no such flight mode"));
}

void HciVehicleLink::takeoff(double altitude, Done done)
{
    command(QStringLiteral("takeoff_command"), {{QStringLiteral("altitude_agl"), altitude}}, std::move(done));
}

void HciVehicleLink::land(Done done)
{
    command(QStringLiteral("land_command"), {}, std::move(done));
}

void HciVehicleLink::returnHome(Done done)
{
    command(QStringLiteral("return_to_home"), {}, std::move(done));
}

void HciVehicleLink::goTo(double latitude, double longitude, double altitude, double speed, Done done)
{
    // HCI speaks radians.
    QVariantMap args{{QStringLiteral("latitude"), radiansFromDegrees(latitude)}, {QStringLiteral("longitude"), radiansFromDegrees(longitude)},
                     {QStringLiteral("altitude_agl"), altitude}};
    if (speed > 0)
        args.insert(QStringLiteral("ground_speed"), speed);
    command(QStringLiteral("waypoint"), args, std::move(done));
}

namespace {

// The server's processed route, which is what UploadRoute sends to the vehicle.
struct HciProcessedMission : NativeMission
{
    explicit HciProcessedMission(const pb::ProcessedRoute &r) : route(r) {}
    pb::ProcessedRoute route;
};

// Empty when every segment was processed; otherwise what the server said about the first one that
// was not ("Segment 3: Altitude 900 m is above ...").
QString processingProblem(const mission::ProcessedPlan &plan)
{
    for (size_t i = 0; i < plan.segments.size(); ++i) {
        const mission::ProcessedSegment &s = plan.segments[i];
        if (s.status == mission::ProcessingStatus::Processed)
            continue;
        QString why;
        for (const auto &m : s.messages) {
            if (m.error || why.isEmpty())
                why = m.text;
            if (m.error)
                break;
        }
        return QCoreApplication::translate("HciVehicleLink", "Segment %1: %2").arg(i + 1).arg(why.isEmpty() ? QCoreApplication::translate("HciVehicleLink", "the server could not process it") : why);
    }
    return {};
}

} // namespace

void HciVehicleLink::prepareMission(const mission::Route &route, PrepareDone done)
{
    pb::Route hciRoute = mission::routeToHci(route);
    if (!hciRoute.has_vehicleprofile() && m_vehicle->has_profile())
        *hciRoute.mutable_vehicleprofile() = m_vehicle->profile();
    if (hciRoute.name().empty())
        hciRoute.set_name(QCoreApplication::translate("HciVehicleLink", "Sortie upload to %1").arg(m_identity.name).toStdString());
    onFinished(m_client->processRoute(hciRoute), [route, done](const HciReply &processed) {
        if (!done)
            return;
        if (!processed.isOk()) {
            done(CommandResult::failure(QCoreApplication::translate("HciVehicleLink", "route processing: %1").arg(processed.error().message())), {});
            return;
        }
        const pb::ProcessedRoute &server = processed.response<pb::ProcessRouteResponse>().processedroute();
        const mission::ProcessedPlan plan = mission::processedPlanFromHci(server, &route);
        if (const QString problem = processingProblem(plan); !problem.isEmpty()) {
            done(CommandResult::failure(problem), {});
            return;
        }
        PreparedMission prepared;
        prepared.native = std::make_shared<HciProcessedMission>(server);
        // Altitudes above home: the ground where the route starts is where the vehicle takes off.
        const double home = plan.waypoints.empty() ? 0.0 : plan.waypoints.front().groundElevation;
        for (const mission::ProcessedWaypoint &w : plan.waypoints)
            prepared.items.push_back({w.position.latitude, w.position.longitude, w.altitudeAmsl - home, w.speed, w.acceptanceRadius, {}});
        for (size_t i = 0; i < plan.segments.size(); ++i) {
            for (const mission::ProcessedMessage &m : plan.segments[i].messages)
                prepared.notices << QCoreApplication::translate("HciVehicleLink", "Segment %1: %2").arg(i + 1).arg(m.text);
        }
        done(CommandResult::success(), prepared);
    });
}

void HciVehicleLink::uploadMission(const PreparedMission &mission, UploadObserver observer, Done done)
{
    const auto processed = std::dynamic_pointer_cast<const HciProcessedMission>(mission.native);
    if (!processed) {
        failLater(std::move(done), QCoreApplication::translate("HciVehicleLink", "upload: the mission was not prepared by the UgCS server"));
        return;
    }
    auto step = [observer](UploadStep s, int value, int maximum) {
        if (observer.step)
            observer.step(s, value, maximum);
    };
    step(UploadStep::Locking, 0, 0);
    hci::underLock<CommandResult>(m_client, HciObjectType::Vehicle, m_vehicle->id(), this, {
        [this, processed, observer, step, count = int(mission.items.size())](auto finish) {
            if (observer.proceed && !observer.proceed()) {
                finish(CommandResult::cancel());
                return;
            }
            step(UploadStep::Sending, 0, 0);
            HciReply *reply = m_client->uploadRoute(*m_vehicle, processed->route);
            connect(reply, &HciReply::progress, this, [step](const QString &, int value, int maximum) { step(UploadStep::Sending, value, maximum); });
            onFinished(reply, [this, finish, count](const HciReply &uploaded) {
                if (!uploaded.isOk()) {
                    finish(CommandResult::failure(QCoreApplication::translate("HciVehicleLink", "upload: %1").arg(uploaded.error().message())));
                    return;
                }
                m_routePass.setUploadedCount(count);
                emit missionChanged();
                finish(CommandResult::success());
            });
        },
        [this](const hci::HciError &refusal) {
            return CommandResult::failure(QCoreApplication::translate("HciVehicleLink", "upload: cannot take control of %1: %2").arg(m_identity.name, refusal.message()));
        },
        [done](CommandResult result) {
            if (done)
                done(result);
        },
        {},
        [step] { step(UploadStep::Releasing, 0, 0); }});
}

void HciVehicleLink::downloadMission(MissionDone done)
{
    QMetaObject::invokeMethod(this, [done] {
        if (done)
            done(CommandResult::failure(QCoreApplication::translate("HciVehicleLink", "a UgCS server does not read a vehicle's mission back")), {});
    }, Qt::QueuedConnection);
}

void HciVehicleLink::readParameters(ParametersDone done)
{
    QVariantMap values;
    for (const auto &p : m_vehicle->profile().parameters())
        values.insert(QString::fromStdString(pb::VehicleParameterType_Name(p.type())), p.value());
    QMetaObject::invokeMethod(this, [done, values] {
        if (done)
            done(CommandResult::success(), values);
    }, Qt::QueuedConnection);
}

void HciVehicleLink::setParameter(const QString &name, double, Done done)
{
    failLater(std::move(done), QCoreApplication::translate("HciVehicleLink", "%1: parameters are set in the vehicle profile on the UgCS server").arg(name));
}

} // namespace sortie::vehicle
