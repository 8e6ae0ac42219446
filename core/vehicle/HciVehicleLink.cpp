#include "HciVehicleLink.h"

#include "HciClient.h"
#include "HciMissionRoute.h"
#include "HciReply.h"
#include "HciSession.h"
#include "HciSubscription.h"
#include "HciTelemetryMapper.h"
#include "Messages.pb.h"

#include <QDateTime>

namespace sortie::vehicle {

namespace pb = com::ugcs::ucs::proto;
using hci::HciObjectType;
using hci::HciReply;

HciVehicleLink::HciVehicleLink(hci::HciClient *client, const pb::Vehicle &vehicle, QObject *parent)
    : VehicleLink(parent)
    , m_client(client)
    , m_vehicle(std::make_unique<pb::Vehicle>(vehicle))
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
    emit stateChanged(s);
}

void HciVehicleLink::start()
{
    if (m_started)
        return;
    m_started = true;
    m_subscription = m_client->subscribeTelemetry(m_vehicle->id());
    connect(m_subscription, &hci::HciSubscription::received, this, &HciVehicleLink::onEvent);
    updateState();
}

void HciVehicleLink::stop()
{
    m_started = false;
    if (m_subscription)
        m_client->session()->unsubscribe(m_subscription);
    updateState();
}

void HciVehicleLink::onEvent(const pb::EventWrapper &event)
{
    if (!event.has_telemetryevent() || event.telemetryevent().vehicle().id() != m_vehicle->id())
        return; // the server may send every vehicle's telemetry
    TelemetryBatch batch = hciTelemetry(event.telemetryevent(), QDateTime::currentMSecsSinceEpoch());
    if (!batch.empty())
        emit telemetryReceived(batch);
}

template<class F>
void HciVehicleLink::onFinished(HciReply *reply, F &&f)
{
    connect(reply, &HciReply::finished, this, [reply, f = std::forward<F>(f)] { f(*reply); });
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
    const int id = m_vehicle->id();
    onFinished(m_client->acquireLock(HciObjectType::Vehicle, id), [this, id, what, work, done](const HciReply &lock) {
        if (!lock.isOk()) {
            if (done)
                done(CommandResult::failure(QStringLiteral("%1: cannot take control of %2: %3").arg(what, m_identity.name, lock.error().message())));
            return;
        }
        work([this, id, done](const CommandResult &result) {
            // Release whatever happened; the result is the work's.
            onFinished(m_client->releaseLock(HciObjectType::Vehicle, id, true), [done, result](const HciReply &) {
                if (done)
                    done(result);
            });
        });
    });
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
            finish(CommandResult::failure(QStringLiteral("%1: the server sent no result for this vehicle").arg(code)));
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
    failLater(std::move(done), QStringLiteral("there is no such flight mode"));
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
    QVariantMap args{{QStringLiteral("latitude"), latitude}, {QStringLiteral("longitude"), longitude},
                     {QStringLiteral("altitude_agl"), altitude}};
    if (speed > 0)
        args.insert(QStringLiteral("ground_speed"), speed);
    command(QStringLiteral("waypoint"), args, std::move(done));
}

void HciVehicleLink::uploadMission(const std::vector<MissionItem> &items, Done done)
{
    if (items.empty()) {
        failLater(std::move(done), QStringLiteral("a mission needs at least one waypoint"));
        return;
    }
    const pb::Route route = hciRouteFor(*m_vehicle, items, QStringLiteral("Sortie upload to %1").arg(m_identity.name));
    onFinished(m_client->processRoute(route), [this, done](const HciReply &processed) {
        if (!processed.isOk()) {
            if (done)
                done(CommandResult::failure(QStringLiteral("route processing: %1").arg(processed.error().message())));
            return;
        }
        const auto plan = std::make_shared<pb::ProcessedRoute>(processed.response<pb::ProcessRouteResponse>().processedroute());
        if (const QString problem = hciProcessingProblem(*plan); !problem.isEmpty()) {
            if (done)
                done(CommandResult::failure(problem));
            return;
        }
        underLock(QStringLiteral("upload"), [this, plan](Done finish) {
            onFinished(m_client->uploadRoute(*m_vehicle, *plan), [this, finish](const HciReply &uploaded) {
                if (!uploaded.isOk()) {
                    finish(CommandResult::failure(QStringLiteral("upload: %1").arg(uploaded.error().message())));
                    return;
                }
                emit missionChanged();
                finish(CommandResult::success());
            });
        }, done);
    });
}

void HciVehicleLink::downloadMission(MissionDone done)
{
    QMetaObject::invokeMethod(this, [done] {
        if (done)
            done(CommandResult::failure(QStringLiteral("a UgCS server does not read a vehicle's mission back")), {});
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
    failLater(std::move(done), QStringLiteral("%1: parameters are set in the vehicle profile on the UgCS server").arg(name));
}

} // namespace sortie::vehicle
