#include "MissionUploader.h"

#include "MissionDifference.h"
#include "VehicleLog.h"

#include <QMetaEnum>

namespace sortie::client {

using vehicle::CommandResult;
using vehicle::VehicleLink;

MissionUploader::MissionUploader(QObject *parent)
    : QObject(parent)
{
}

MissionUploader::~MissionUploader()
{
    ++m_run; // nothing that is still on its way reaches a destroyed uploader's state
}

QString MissionUploader::stateName(State state)
{
    return QString::fromLatin1(QMetaEnum::fromType<State>().valueToKey(int(state)));
}

bool MissionUploader::isBusy() const
{
    switch (m_state) {
    case State::Idle:
    case State::Done:
    case State::Failed:
    case State::Cancelled: return false;
    default: return true;
    }
}

bool MissionUploader::canCancel() const
{
    switch (m_state) {
    case State::Validating:
    case State::AwaitingConfirmation:
    case State::Processing:
    case State::Locking: return !m_cancelRequested;
    default: return false;
    }
}

QString MissionUploader::activity() const
{
    switch (m_state) {
    case State::Validating: return tr("Checking the route");
    case State::AwaitingConfirmation: return tr("Waiting for your answer");
    case State::Processing: return tr("Processing for %1").arg(m_vehicleName);
    case State::Locking: return tr("Taking control of %1").arg(m_vehicleName);
    case State::Uploading: return tr("Uploading to %1").arg(m_vehicleName);
    case State::Releasing: return tr("Releasing %1").arg(m_vehicleName);
    case State::Verifying: return tr("Reading the mission back from %1").arg(m_vehicleName);
    default: return {};
    }
}

QString MissionUploader::question() const
{
    return m_state == State::AwaitingConfirmation ? m_review.question(m_vehicleName) : QString();
}

template<class F>
auto MissionUploader::current(F &&f)
{
    return [self = QPointer<MissionUploader>(this), run = m_run, f = std::forward<F>(f)](auto &&...args) {
        if (self && self->m_run == run)
            f(std::forward<decltype(args)>(args)...);
    };
}

bool MissionUploader::start(const mission::Route &route, vehicle::Vehicle *vehicle, bool unsavedEdits)
{
    if (isBusy() || !vehicle)
        return false;
    ++m_run;
    m_cancelRequested = false;
    m_vehicle = vehicle;
    m_vehicleName = vehicle->name();
    m_route = route;
    m_prepared = {};
    setProgress(0, 0);
    m_logEntry = m_log ? m_log->track(m_vehicleName, tr("upload \"%1\"").arg(route.settings.name.isEmpty() ? tr("route") : route.settings.name))
                       : std::function<void(const CommandResult &)>();
    // A vehicle that goes away (its server session ended) takes the upload with it.
    connect(vehicle, &QObject::destroyed, this, current([this](QObject *) {
        end(State::Failed, tr("Upload to %1 failed: the vehicle is gone (its connection was closed).").arg(m_vehicleName),
            CommandResult::failure(tr("the vehicle is gone")));
    }));
    setState(State::Validating);
    m_review = reviewUpload(validate(route), unsavedEdits);
    if (m_review.isBlocked()) {
        end(State::Failed, tr("Not uploaded: %1").arg(m_review.blocked), CommandResult::failure(m_review.blocked));
        return true;
    }
    if (m_review.needsConfirmation()) {
        setMessage(m_review.question(m_vehicleName));
        setState(State::AwaitingConfirmation);
        return true;
    }
    process();
    return true;
}

mission::ValidationReport MissionUploader::validate(const mission::Route &route) const
{
    return m_validator ? m_validator(route) : mission::validateRoute(route);
}

void MissionUploader::confirm()
{
    if (m_state == State::AwaitingConfirmation)
        process();
}

void MissionUploader::confirm(const mission::Route &route, bool unsavedEdits)
{
    if (m_state != State::AwaitingConfirmation)
        return;
    const QStringList asked = m_review.warnings;
    m_route = route;
    m_review = reviewUpload(validate(route), unsavedEdits);
    if (m_review.isBlocked())
        return end(State::Failed, tr("Not uploaded: %1").arg(m_review.blocked), CommandResult::failure(m_review.blocked));
    bool news = m_review.unsavedEdits;
    for (const QString &w : m_review.warnings)
        news = news || !asked.contains(w);
    if (news) {
        setMessage(m_review.question(m_vehicleName));
        emit stateChanged(); // the question changed
        return;
    }
    process();
}

void MissionUploader::cancel()
{
    if (!canCancel()) {
        if (isBusy())
            setMessage(tr("Too late to cancel: the mission is being sent to %1.").arg(m_vehicleName));
        return;
    }
    if (m_state == State::Locking) {
        // The link asks before sending, then releases the lock; its answer ends the upload.
        m_cancelRequested = true;
        emit stateChanged();
        return;
    }
    end(State::Cancelled, tr("Upload to %1 cancelled; nothing was sent.").arg(m_vehicleName), CommandResult::cancel());
}

void MissionUploader::process()
{
    VehicleLink *link = m_vehicle ? m_vehicle->link() : nullptr;
    if (!link)
        return end(State::Failed, tr("Upload to %1 failed: the vehicle has no link.").arg(m_vehicleName), CommandResult::failure(tr("no link")));
    setState(State::Processing);
    const bool keepsFence = link->capabilities().testFlag(VehicleLink::Fence);
    link->prepareMissionWithFence(m_route, m_fence, current([this, keepsFence](const CommandResult &result, const vehicle::PreparedMission &prepared) {
        if (!result.ok)
            return end(State::Failed, tr("Not uploaded to %1: %2").arg(m_vehicleName, result.message), result);
        m_prepared = prepared;
        // Said, not hidden: the route's fence stays on the ground for a vehicle that keeps none.
        if (!keepsFence && (!m_route.fence.polygons.empty() || !m_route.fence.circles.empty()))
            m_prepared.notices.append(tr("the route's fence is not sent: %1 keeps no fence (HCI)").arg(m_vehicleName));
        send();
    }));
}

void MissionUploader::send()
{
    VehicleLink *link = m_vehicle ? m_vehicle->link() : nullptr;
    if (!link)
        return end(State::Failed, tr("Upload to %1 failed: the vehicle has no link.").arg(m_vehicleName), CommandResult::failure(tr("no link")));
    setState(State::Locking);
    VehicleLink::UploadObserver observer;
    observer.proceed = [self = QPointer<MissionUploader>(this), run = m_run] {
        return self && self->m_run == run && !self->m_cancelRequested;
    };
    observer.step = current([this](vehicle::UploadStep step, int value, int maximum) {
        switch (step) {
        case vehicle::UploadStep::Locking: setState(State::Locking); break;
        case vehicle::UploadStep::Sending: setState(State::Uploading); break;
        case vehicle::UploadStep::Releasing: setState(State::Releasing); break;
        }
        setProgress(value, maximum);
    });
    link->uploadMission(m_prepared, observer, current([this](const CommandResult &result) {
        if (result.cancelled)
            return end(State::Cancelled, tr("Upload to %1 cancelled; nothing was sent.").arg(m_vehicleName), result);
        if (!result.ok)
            return end(State::Failed, tr("Upload to %1 failed: %2").arg(m_vehicleName, result.message), result);
        VehicleLink *link = m_vehicle ? m_vehicle->link() : nullptr;
        if (link && link->capabilities().testFlag(VehicleLink::MissionDownload))
            return verify();
        succeed(m_prepared.items);
    }));
}

void MissionUploader::verify()
{
    setState(State::Verifying);
    setProgress(0, 0);
    m_vehicle->link()->downloadMission(current([this](const CommandResult &result, const std::vector<vehicle::MissionItem> &held) {
        if (!result.ok)
            return end(State::Failed, tr("Uploaded to %1, but it could not be read back: %2").arg(m_vehicleName, result.message), result);
        const QString difference = vehicle::missionDifference(m_prepared.items, held);
        if (!difference.isEmpty())
            return end(State::Failed, tr("Uploaded to %1, but it holds something else: %2").arg(m_vehicleName, difference),
                       CommandResult::failure(difference));
        succeed(held);
    }));
}

void MissionUploader::succeed(std::vector<vehicle::MissionItem> held)
{
    const int count = int(held.size());
    if (m_vehicle)
        m_vehicle->setMission(std::move(held));
    QString text = tr("Uploaded to %1: %n waypoint(s).", nullptr, count).arg(m_vehicleName);
    if (!m_prepared.notices.isEmpty())
        text += QLatin1Char(' ') + tr("Note: %1").arg(m_prepared.notices.join(QStringLiteral("; ")));
    vehicle::Vehicle *target = m_vehicle;
    end(State::Done, text, CommandResult::success());
    if (target)
        emit uploaded(target);
}

void MissionUploader::end(State state, const QString &message, const CommandResult &logged)
{
    ++m_run; // late answers of this upload are ignored from now on
    if (m_vehicle)
        disconnect(m_vehicle, &QObject::destroyed, this, nullptr);
    if (m_logEntry) {
        m_logEntry(logged);
        m_logEntry = nullptr;
    }
    if (state == State::Done)
        qCInfo(lcVehicle).noquote() << message;
    else
        qCWarning(lcVehicle).noquote() << message;
    setProgress(0, 0);
    setMessage(message);
    setState(state);
    emit finished(state == State::Done);
}

void MissionUploader::setState(State state)
{
    if (state == m_state)
        return;
    m_state = state;
    emit stateChanged();
}

void MissionUploader::setMessage(const QString &message)
{
    m_message = message;
    emit messageChanged();
}

void MissionUploader::setProgress(int value, int maximum)
{
    if (value == m_progressValue && maximum == m_progressMaximum)
        return;
    m_progressValue = value;
    m_progressMaximum = maximum;
    emit progressChanged();
}

} // namespace sortie::client
