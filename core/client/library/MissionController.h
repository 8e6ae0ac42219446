#pragma once

#include "AlgorithmCatalog.h"
#include "HciProto.h"
#include "RouteConflict.h"
#include "RouteDocument.h"
#include "RoutePreparation.h"
#include "ServerObjectListModel.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <map>
#include <memory>

namespace sortie::hci {
class HciClient;
class HciReply;
class HciSubscription;
} // namespace sortie::hci

namespace sortie::client {

// The route library: the server's routes to pick from, the one open for editing (a RouteDocument),
// saving it under a lock, noticing when someone else changed it meanwhile (and offering a clear
// choice: keep ours or take theirs). Edits stay in the document whatever the connection does:
// opening a route over unsaved edits first asks (Save, Discard, Cancel; a question posed as state,
// which the view only shows), and what is discarded is one undo step away; an edit made while a
// save is in flight is laid over the server's copy rather than lost. What the open route becomes
// for a vehicle (Process, Upload) is its RoutePreparation's.
class MissionController : public QObject
{
    Q_OBJECT
    Q_PROPERTY(sortie::client::ServerObjectListModel *routes READ routes CONSTANT)
    // The server's vehicle objects (uploads go to the fleet's vehicles, HCI and VCI alike).
    Q_PROPERTY(sortie::client::ServerObjectListModel *vehicles READ vehicles CONSTANT)
    Q_PROPERTY(sortie::client::RouteDocument *document READ document CONSTANT)
    // The open route made ready for a vehicle: the chosen vehicle, Process, Upload.
    Q_PROPERTY(sortie::client::RoutePreparation *preparation READ preparation CONSTANT)
    Q_PROPERTY(int routeId READ routeId NOTIFY routeChanged)
    Q_PROPERTY(QString routeName READ routeName NOTIFY routeChanged)
    // Whether Save means something: a route from the server is open, or a new one has edits.
    Q_PROPERTY(bool canSave READ canSave NOTIFY canSaveChanged)
    Q_PROPERTY(bool conflict READ hasConflict NOTIFY conflictChanged)
    Q_PROPERTY(QString conflictText READ conflictText NOTIFY conflictChanged)
    // The server's copy beside ours: differences, each side's edits, versions, their route.
    Q_PROPERTY(sortie::client::RouteConflict *conflictDetails READ conflictDetails CONSTANT)
    Q_PROPERTY(bool busy READ isBusy NOTIFY activityChanged)
    Q_PROPERTY(QString activity READ activity NOTIFY activityChanged)
    Q_PROPERTY(int progressValue READ progressValue NOTIFY progressChanged)
    Q_PROPERTY(int progressMaximum READ progressMaximum NOTIFY progressChanged)
    Q_PROPERTY(QString message READ message NOTIFY messageChanged)
    // openRoute() waits for an answer: the open route has unsaved edits (saveThenOpen,
    // discardThenOpen, cancelOpen).
    Q_PROPERTY(bool askingToOpen READ isAskingToOpen NOTIFY openQuestionChanged)
    Q_PROPERTY(QString openQuestion READ openQuestion NOTIFY openQuestionChanged)

public:
    explicit MissionController(hci::HciClient *client, QObject *parent = nullptr);
    ~MissionController() override;

    ServerObjectListModel *routes() { return &m_routes; }
    ServerObjectListModel *vehicles() { return &m_vehicles; }
    RouteDocument *document() { return &m_document; }
    RoutePreparation *preparation() { return &m_preparation; }
    int routeId() const;
    QString routeName() const { return m_document.route().settings.name; }
    bool canSave() const;
    bool hasConflict() const { return m_conflict.isActive(); }
    RouteConflict *conflictDetails() { return &m_conflict; }
    QString conflictText() const { return m_conflictText; }
    bool isBusy() const { return !m_activity.isEmpty(); }
    QString activity() const { return m_activity; }
    int progressValue() const { return m_progressValue; }
    int progressMaximum() const { return m_progressMaximum; }
    QString message() const { return m_message; }
    bool isAskingToOpen() const { return m_askingToOpen >= 0; }
    QString openQuestion() const;

    // Reads the server's routes and vehicles (done by itself whenever the session becomes ready).
    Q_INVOKABLE void refresh();
    // Opens the server's route (again, if it is the one open). Over unsaved edits it asks first.
    Q_INVOKABLE void openRoute(int routeId);
    // The answers to `openQuestion`. Save: the route asked about opens once the save succeeded (a
    // save that fails or meets a conflict leaves it open, as a save does). Discard: it opens as
    // one undo step, so Undo brings the edits back. Cancel: nothing happens.
    Q_INVOKABLE void saveThenOpen();
    Q_INVOKABLE void discardThenOpen();
    Q_INVOKABLE void cancelOpen();
    // Saves under the route's lock, unless validation finds an error (the message names it). When
    // the server's copy changed since it was opened, nothing is overwritten: `conflict` says so and
    // keepMine() or takeTheirs() decides.
    Q_INVOKABLE void save();
    Q_INVOKABLE void keepMine();
    // Their copy replaces ours as one undoable step (marked as saved: it is the server's), so
    // undo brings our edits back.
    Q_INVOKABLE void takeTheirs();

signals:
    void routeChanged();
    void canSaveChanged();
    // A route was opened from the server (not saved, not edited): views frame it.
    void routeOpened();
    void conflictChanged();
    void activityChanged();
    void progressChanged();
    void messageChanged();
    void openQuestionChanged();
    void saved(int version);

private:
    template<typename Done>
    void request(hci::HciReply *reply, const QString &activity, Done done);
    void setActivity(const QString &activity);
    void setProgress(int value, int maximum);
    void setMessage(const QString &message);
    // A message worded again when the operator's language changes ("Opened … (version n)"): its
    // words are made by `words`, from values it captured.
    void setMessage(std::function<QString()> words);
    void setConflict(const com::ugcs::ucs::proto::Route *theirs, const QString &text);
    void fetchAndOpen(int routeId);
    void askToOpen(int routeId);
    // A save that did not happen: says why, and forgets the open that was to follow it.
    void notSaved(const QString &message);
    void writeLocked(const com::ugcs::ucs::proto::Route &route);
    void written(const hci::HciReply &reply, int routeId);
    void routeEvent(const com::ugcs::ucs::proto::EventWrapper &event);
    mission::ValidationReport validation();

    QPointer<hci::HciClient> m_client;
    ServerObjectListModel m_routes;
    ServerObjectListModel m_vehicles;
    std::map<int, std::unique_ptr<com::ugcs::ucs::proto::Vehicle>> m_vehicleObjects;
    mission::AlgorithmCatalog m_catalog;  // the server's algorithms, once listed (the document's editor uses it)
    RouteDocument m_document;
    RoutePreparation m_preparation{&m_document};
    RouteConflict m_conflict; // the server's copy, when it differs
    mission::Route m_sent;    // what the save in flight sent: edits made after it are not saved by it
    int m_askingToOpen = -1;  // the route openQuestion is about
    int m_openAfterSave = -1; // the route saveThenOpen() opens once the save succeeded
    QString m_conflictText;
    QString m_activity;
    int m_progressValue = 0;
    int m_progressMaximum = 0;
    QString m_message;
    std::function<QString()> m_messageWords; // how m_message was worded, when it can be again
    hci::HciSubscription *m_routeEvents = nullptr;
    bool m_saving = false; // our own save's change event is not someone else's
};

} // namespace sortie::client
