#pragma once

#include "Route.h"
#include "UploadReview.h"
#include "Vehicle.h"

#include <QObject>
#include <QPointer>

namespace sortie::client {

// The one way a route reaches a vehicle, whichever protocol carries it: validate (errors refuse,
// warnings and unsaved edits are asked about once), process (VehicleLink::prepareMission: the UgCS
// server for HCI, a local expansion for VCI), lock, upload and release (VehicleLink::uploadMission),
// then verify by reading the mission back where the vehicle can (VCI). Only a confirmed upload sets
// the Vehicle's mission. One upload at a time; the UI, the tests and any script drive it the same
// way: start(), confirm() when asked, cancel() until the mission is being sent.
class MissionUploader : public QObject
{
    Q_OBJECT
    Q_PROPERTY(State state READ state NOTIFY stateChanged)
    Q_PROPERTY(bool busy READ isBusy NOTIFY stateChanged)
    Q_PROPERTY(bool canCancel READ canCancel NOTIFY stateChanged)
    Q_PROPERTY(QString activity READ activity NOTIFY stateChanged)
    Q_PROPERTY(QString vehicleName READ vehicleName NOTIFY stateChanged)
    Q_PROPERTY(bool asking READ isAsking NOTIFY stateChanged) // AwaitingConfirmation
    Q_PROPERTY(QString question READ question NOTIFY stateChanged)
    Q_PROPERTY(bool unsavedEdits READ hasUnsavedEdits NOTIFY stateChanged)
    Q_PROPERTY(int culprit READ culprit NOTIFY stateChanged)
    Q_PROPERTY(QString message READ message NOTIFY messageChanged)
    Q_PROPERTY(int progressValue READ progressValue NOTIFY progressChanged)
    Q_PROPERTY(int progressMaximum READ progressMaximum NOTIFY progressChanged)

public:
    enum class State {
        Idle,
        Validating,
        AwaitingConfirmation, // `question` waits for confirm() or cancel()
        Processing,
        Locking,
        Uploading,
        Releasing,
        Verifying,
        Done,
        Failed,
        Cancelled,
    };
    Q_ENUM(State)

    explicit MissionUploader(QObject *parent = nullptr);
    ~MissionUploader() override;

    // Where every upload and its result is recorded (not owned; none by default).
    void setCommandLog(vehicle::CommandLog *log) { m_log = log; }
    // How a route is validated: mission::validateRoute by default; the editor's analyzer, with the
    // rules other libraries add to it (terrain clearance), when the route is the open document.
    using Validator = std::function<mission::ValidationReport(const mission::Route &)>;
    void setValidator(Validator validator) { m_validator = std::move(validator); }
    // What goes up beside the route to a vehicle that keeps a fence (VCI): the zones the client
    // checks routes against and the breach action (return home by default). HCI vehicles keep none.
    void setFenceSettings(vehicle::FenceSettings settings) { m_fence = std::move(settings); }
    const vehicle::FenceSettings &fenceSettings() const { return m_fence; }

    State state() const { return m_state; }
    bool isBusy() const;
    bool canCancel() const;
    bool isAsking() const { return m_state == State::AwaitingConfirmation; }
    QString activity() const;
    QString vehicleName() const { return m_vehicleName; }
    QString question() const;
    bool hasUnsavedEdits() const { return m_review.unsavedEdits; }
    int culprit() const { return m_review.culprit; }
    QString message() const { return m_message; }
    int progressValue() const { return m_progressValue; }
    int progressMaximum() const { return m_progressMaximum; }
    // The route of the current or last upload, as it goes up (after "save, then upload": as saved).
    const mission::Route &route() const { return m_route; }
    // What the vehicle was sent, once processed.
    const std::vector<vehicle::MissionItem> &mission() const { return m_prepared.items; }

    // Starts uploading `route` to `vehicle`. False (and nothing changes) while another upload runs.
    // `unsavedEdits`: the route differs from what is saved; the operator is asked.
    bool start(const mission::Route &route, vehicle::Vehicle *vehicle, bool unsavedEdits = false);
    // The operator accepted the warnings and unsaved edits in `question`.
    Q_INVOKABLE void confirm();
    // The operator answered "save, then upload": `route` as saved replaces the one asked about and is
    // checked again; only warnings that were not listed in the question are asked about.
    void confirm(const mission::Route &route, bool unsavedEdits);
    // Stops the upload before the mission is sent: at once while validating, asking or processing;
    // while locking, as soon as the lock is answered (and released again). Too late once sending.
    Q_INVOKABLE void cancel();

    static QString stateName(State state);

signals:
    void stateChanged();
    void messageChanged();
    void progressChanged();
    // The end of an upload: Done, Failed or Cancelled, with `message` saying what happened.
    void finished(bool ok);
    // The vehicle holds the uploaded mission (after verification where the vehicle can be read).
    void uploaded(sortie::vehicle::Vehicle *vehicle);

private:
    void setState(State state);
    void setMessage(const QString &message);
    void setProgress(int value, int maximum);
    mission::ValidationReport validate(const mission::Route &route) const;
    void process();
    void send();
    void verify();
    void succeed(std::vector<vehicle::MissionItem> held);
    void end(State state, const QString &message, const vehicle::CommandResult &logged);
    // A callback that runs only while the upload it was made for is still the current one.
    template<class F>
    auto current(F &&f);

    QPointer<vehicle::Vehicle> m_vehicle;
    QPointer<vehicle::CommandLog> m_log;
    Validator m_validator;
    vehicle::FenceSettings m_fence;
    mission::Route m_route;
    UploadReview m_review;
    vehicle::PreparedMission m_prepared;
    std::function<void(const vehicle::CommandResult &)> m_logEntry;
    QString m_vehicleName;
    QString m_message;
    State m_state = State::Idle;
    quint64 m_run = 0;          // which upload the callbacks belong to
    bool m_cancelRequested = false;
    int m_progressValue = 0;
    int m_progressMaximum = 0;
};

} // namespace sortie::client
