#include "MissionController.h"

#include "AlgorithmProto.h"

#include "HciClient.h"
#include "HciLock.h"
#include "HciOrigin.h"
#include "HciReply.h"
#include "HciRouteMapper.h"
#include "HciSession.h"
#include "HciSubscription.h"
#include "LanguageChange.h"
#include "Messages.pb.h"
#include "RouteValidator.h"
#include "SavedRouteMerge.h"
#include "UploadReview.h"

#include <utility>

namespace sortie::client {

using namespace sortie::mission;
namespace pb = com::ugcs::ucs::proto;
using hci::HciObjectType;
using hci::HciReply;

MissionController::MissionController(hci::HciClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    hci::HciSession *session = client->session();
    connect(session, &hci::HciSession::ready, this, &MissionController::refresh);
    m_routeEvents = client->subscribeObjectChanges(HciObjectType::Route);
    connect(m_routeEvents, &hci::HciSubscription::received, this, &MissionController::routeEvent);
    connect(m_document.undoStack(), &QUndoStack::indexChanged, this, &MissionController::routeChanged);
    connect(this, &MissionController::routeChanged, this, &MissionController::canSaveChanged);
    connect(&m_document, &RouteDocument::modifiedChanged, this, &MissionController::canSaveChanged);
    i18n::onLanguageChange(this, [this] {
        if (m_messageWords)
            setMessage(m_messageWords);
        if (isAskingToOpen())
            emit openQuestionChanged();
    });
    connect(&m_preparation, &RoutePreparation::saveRequested, this, &MissionController::save);
    connect(this, &MissionController::saved, &m_preparation, &RoutePreparation::routeSaved);
}

MissionController::~MissionController() = default;

int MissionController::routeId() const
{
    const auto &origin = m_document.route().origin;
    return origin && hciRoute(origin)->has_id() ? hciRoute(origin)->id() : -1;
}

bool MissionController::canSave() const
{
    return routeId() >= 0 || m_document.isModified();
}

template<typename Done>
void MissionController::request(HciReply *reply, const QString &activity, Done done)
{
    setActivity(activity);
    setProgress(0, 0);
    connect(reply, &HciReply::progress, this, [this](const QString &, int value, int maximum) { setProgress(value, maximum); });
    connect(reply, &HciReply::finished, this, [this, reply, done] {
        setActivity({});
        done(reply);
    });
}

void MissionController::refresh()
{
    if (!m_client || !m_client->session()->isReady())
        return;
    request(m_client->listObjects(HciObjectType::Route), tr("Reading the server's routes"), [this](HciReply *reply) {
        if (!reply->isOk())
            return setMessage(tr("The server's routes could not be read: %1").arg(reply->error().message()));
        std::vector<ServerObjectListModel::Entry> entries;
        for (const pb::DomainObjectWrapper &object : reply->response<pb::GetObjectListResponse>().objects()) {
            const pb::Route &route = object.route();
            const QString mission = QString::fromStdString(route.mission().name());
            entries.push_back({route.id(), QString::fromStdString(route.name()),
                               tr("%1%n segment(s)", nullptr, route.segments_size())
                                   .arg(mission.isEmpty() ? QString() : mission + QStringLiteral(" · "))});
        }
        std::sort(entries.begin(), entries.end(), [](const auto &a, const auto &b) { return a.name < b.name; });
        m_routes.setEntries(std::move(entries));
    });
    // The server's algorithms and their parameters: what the segment editor is built from. A
    // server that does not list them leaves the built-in descriptions in place.
    HciReply *algorithms = m_client->listObjects(HciObjectType::TraverseAlgorithm);
    connect(algorithms, &HciReply::finished, this, [this, algorithms] {
        if (!algorithms->isOk())
            return;
        std::vector<pb::TraverseAlgorithm> list;
        for (const pb::DomainObjectWrapper &object : algorithms->response<pb::GetObjectListResponse>().objects())
            if (object.has_traversealgorithm())
                list.push_back(object.traversealgorithm());
        if (list.empty())
            return;
        m_catalog = mission::catalogFromProto(list);
        m_document.editor()->setCatalog(&m_catalog);
    });
    request(m_client->listObjects(HciObjectType::Vehicle), tr("Reading the server's vehicles"), [this](HciReply *reply) {
        if (!reply->isOk())
            return;
        std::vector<ServerObjectListModel::Entry> entries;
        for (const pb::DomainObjectWrapper &object : reply->response<pb::GetObjectListResponse>().objects()) {
            const pb::Vehicle &vehicle = object.vehicle();
            entries.push_back({vehicle.id(), QString::fromStdString(vehicle.name()), QString::fromStdString(vehicle.serialnumber())});
        }
        m_vehicles.setEntries(std::move(entries));
    });
}

void MissionController::openRoute(int routeId)
{
    if (!m_client)
        return;
    if (m_document.isModified())
        return askToOpen(routeId);
    fetchAndOpen(routeId);
}

void MissionController::askToOpen(int routeId)
{
    m_askingToOpen = routeId;
    emit openQuestionChanged();
}

QString MissionController::openQuestion() const
{
    if (!isAskingToOpen())
        return {};
    const QString mine = routeName().isEmpty() ? tr("The new route") : tr("\"%1\"").arg(routeName());
    const int row = m_routes.rowOf(m_askingToOpen);
    const QString theirs = row >= 0 ? m_routes.nameAt(row) : QString();
    const QString question = m_askingToOpen == routeId()
        ? tr("%1 has unsaved edits. Opening it again reads the server's copy. Save your edits first?").arg(mine)
        : tr("%1 has unsaved edits. Save them before opening \"%2\"?").arg(mine, theirs);
    return question + QLatin1Char(' ') + tr("If you discard them, Undo brings them back.");
}

void MissionController::saveThenOpen()
{
    if (!isAskingToOpen())
        return;
    const int id = std::exchange(m_askingToOpen, -1);
    emit openQuestionChanged();
    m_openAfterSave = id;
    save();
}

void MissionController::discardThenOpen()
{
    if (!isAskingToOpen())
        return;
    const int id = std::exchange(m_askingToOpen, -1);
    emit openQuestionChanged();
    fetchAndOpen(id);
}

void MissionController::cancelOpen()
{
    if (!isAskingToOpen())
        return;
    m_askingToOpen = -1;
    emit openQuestionChanged();
}

void MissionController::fetchAndOpen(int routeId)
{
    request(m_client->getObject(HciObjectType::Route, routeId), tr("Opening the route"), [this](HciReply *reply) {
        if (!reply->isOk())
            return setMessage(tr("The route could not be opened: %1").arg(reply->error().message()));
        auto imported = routeFromHci(reply->response<pb::GetObjectResponse>().object().route());
        if (!imported)
            return setMessage(tr("The route cannot be edited here: %1").arg(imported.error().toString()));
        setConflict(nullptr, {});
        // Unsaved edits here (discarded by the operator, or made while the route was read) stay
        // one undo step away.
        const bool kept = m_document.isModified();
        const QString discarded = routeName().isEmpty() ? tr("the new route") : routeName();
        m_document.open(imported->route, tr("Open %1").arg(imported->route.settings.name));
        // The import's notices are sentences already made: they keep their language.
        const QString notices = imported->notices.isEmpty() ? QString() : QLatin1Char(' ') + imported->notices.join(QLatin1Char(' '));
        setMessage([name = routeName(), version = reply->response<pb::GetObjectResponse>().object().route().version(), notices,
                    kept, discarded] {
            QString text = tr("Opened %1 (version %2).").arg(name).arg(version);
            if (kept)
                text += QLatin1Char(' ') + tr("Undo brings back your unsaved edits of %1.").arg(discarded);
            return text + notices;
        });
        emit routeChanged();
        emit routeOpened();
    });
}

void MissionController::save()
{
    if (!m_client || !m_client->session()->isReady())
        return notSaved(tr("Not connected: your edits are kept; save again when the connection is back."));
    if (isBusy())
        return notSaved(tr("Wait until %1 is done.").arg(m_activity.toLower()));
    // The validation gate: nothing with an error is saved (the message names the culprit).
    if (const QString refused = saveRefusal(validation()); !refused.isEmpty())
        return notSaved(tr("Not saved: %1").arg(refused));
    const int id = routeId();
    if (id < 0) {
        m_saving = true;
        m_sent = m_document.route();
        request(m_client->createOrUpdate(routeToHci(m_document.route())), tr("Saving"), [this](HciReply *reply) {
            m_saving = false;
            written(*reply, -1);
        });
        return;
    }
    writeLocked(routeToHci(m_document.route()));
}

void MissionController::writeLocked(const pb::Route &route)
{
    // The reply is kept until the lock is released, then handled.
    struct Written
    {
        std::shared_ptr<HciReply> reply;
        QString refusal;
    };
    const int id = route.id();
    m_sent = m_document.route();
    setActivity(tr("Locking the route"));
    hci::underLock<Written>(m_client, HciObjectType::Route, id, this, {
        [this, route, id](auto finish) {
            if (id != routeId())
                return finish(Written{}); // another route was opened meanwhile
            setActivity(tr("Saving"));
            m_saving = true;
            HciReply *reply = m_client->createOrUpdate(route);
            reply->setAutoDelete(false);
            connect(reply, &HciReply::progress, this, [this](const QString &, int value, int maximum) { setProgress(value, maximum); });
            connect(reply, &HciReply::finished, this, [reply, finish] {
                finish(Written{std::shared_ptr<HciReply>(reply, [](HciReply *r) { r->deleteLater(); }), {}});
            });
        },
        [](const hci::HciError &refusal) { return Written{nullptr, refusal.message()}; },
        [this, id](Written outcome) {
            m_saving = false;
            setActivity({});
            if (!outcome.refusal.isEmpty())
                return notSaved(tr("Not saved: the route is locked (%1).").arg(outcome.refusal));
            if (!outcome.reply)
                return notSaved(tr("Not saved: another route was opened meanwhile."));
            written(*outcome.reply, id);
        },
        {}, {}});
}

void MissionController::written(const HciReply &reply, int id)
{
    if (!reply.isOk()) {
        if (id < 0 || reply.error().kind() != hci::HciError::Kind::Server)
            return notSaved(tr("Not saved: %1").arg(reply.error().message()));
        // Refused: find out whether someone else saved a newer version meanwhile.
        m_openAfterSave = -1;
        const QString refusal = reply.error().message();
        request(m_client->getObject(HciObjectType::Route, id), tr("Reading the server's copy"), [this, refusal](HciReply *check) {
            const pb::Route &theirs = check->response<pb::GetObjectResponse>().object().route();
            const auto &origin = m_document.route().origin;
            if (check->isOk() && origin && theirs.version() > hciRoute(origin)->version())
                return setConflict(&theirs, tr("Someone else saved this route on the server (version %1) after you opened it (version %2).")
                                                .arg(theirs.version()).arg(hciRoute(origin)->version()));
            setMessage(tr("Not saved: %1").arg(refusal));
        });
        return;
    }
    const pb::Route &stored = reply.response<pb::CreateOrUpdateObjectResponse>().object().route();
    auto imported = routeFromHci(stored);
    if (!imported)
        return notSaved(tr("Saved, but the server's answer cannot be read back: %1").arg(imported.error().toString()));
    // The server's copy becomes the baseline; edits made while the save was in flight are not in
    // it, so they go over it as one undo step, still unsaved.
    const bool editedMeanwhile = !(m_document.route() == m_sent);
    mission::Route current = editedMeanwhile ? m_document.route() : mission::Route{};
    m_document.load(imported->route);
    if (editedMeanwhile)
        m_document.editor()->replaceRoute(overSavedRoute(std::move(current), m_sent, imported->route), tr("Edits made while saving"));
    m_sent = {};
    setConflict(nullptr, {});
    setMessage([name = routeName(), version = stored.version(), editedMeanwhile] {
        const QString text = tr("Saved %1 (version %2).").arg(name).arg(version);
        return editedMeanwhile ? text + QLatin1Char(' ') + tr("The edits you made while it was saving are kept, not saved yet.") : text;
    });
    emit routeChanged();
    emit saved(stored.version());
    refresh();
    if (const int next = std::exchange(m_openAfterSave, -1); next >= 0)
        openRoute(next); // asks again if edits were made while saving
}

void MissionController::notSaved(const QString &message)
{
    m_openAfterSave = -1;
    setMessage(message);
}

void MissionController::keepMine()
{
    if (!hasConflict())
        return;
    const int theirVersion = m_conflict.theirVersion();
    setConflict(nullptr, {});
    pb::Route mine = routeToHci(m_document.route());
    mine.set_version(theirVersion); // ours replaces theirs, knowingly
    writeLocked(mine);
}

void MissionController::takeTheirs()
{
    if (!hasConflict())
        return;
    Route theirs = m_conflict.theirRoute();
    setConflict(nullptr, {});
    m_document.editor()->replaceRoute(std::move(theirs), tr("Take the server's version"));
    m_document.undoStack()->setClean(); // what the server has: nothing unsaved
    setMessage([] { return tr("This is the server's copy now. Undo brings your edits back."); });
    emit routeChanged();
}

void MissionController::routeEvent(const pb::EventWrapper &event)
{
    const pb::ObjectModificationEvent &change = event.objectmodificationevent();
    refresh();
    const auto &origin = m_document.route().origin;
    if (m_saving || !origin || change.objectid() != routeId())
        return;
    if (change.modificationtype() == pb::MT_DELETE) {
        setMessage([] { return tr("This route was deleted on the server. Your copy stays open."); });
        return;
    }
    const pb::Route &theirs = change.object().route();
    if (!change.object().has_route() || theirs.version() <= hciRoute(origin)->version())
        return;
    if (!m_document.isModified()) {
        // Nothing of ours to lose: follow the server.
        if (auto imported = routeFromHci(theirs)) {
            // As one undo step when undo holds something (edits an open or Take theirs set aside).
            m_document.open(imported->route, tr("Update from the server (version %1)").arg(theirs.version()));
            setMessage([version = theirs.version()] { return tr("Updated from the server (version %1).").arg(version); });
            emit routeChanged();
        }
        return;
    }
    setConflict(&theirs, tr("Someone else saved this route on the server (version %1) while you were editing it.")
                             .arg(theirs.version()));
}

mission::ValidationReport MissionController::validation()
{
    // The analyzer's report: every rule, those other libraries add to it (terrain) included.
    m_document.analyzer()->recomputeNow();
    return m_document.analyzer()->validation();
}

void MissionController::setActivity(const QString &activity)
{
    if (activity == m_activity)
        return;
    m_activity = activity;
    emit activityChanged();
}

void MissionController::setProgress(int value, int maximum)
{
    m_progressValue = value;
    m_progressMaximum = maximum;
    emit progressChanged();
}

void MissionController::setMessage(const QString &message)
{
    m_messageWords = nullptr;
    m_message = message;
    emit messageChanged();
}

void MissionController::setMessage(std::function<QString()> words)
{
    m_message = words();
    m_messageWords = std::move(words);
    emit messageChanged();
}

void MissionController::setConflict(const pb::Route *theirs, const QString &text)
{
    if (!theirs || !m_conflict.set(*theirs, m_document.route(), m_document.baseline()))
        m_conflict.clear();
    m_conflictText = m_conflict.isActive() ? text : QString();
    emit conflictChanged();
}

} // namespace sortie::client
