#include "RoutePreparation.h"

#include "RouteAnalyzer.h"
#include "RouteDocument.h"
#include "Vehicle.h"
#include "VehicleFleet.h"
#include "VehicleLink.h"

#include <QUndoStack>

#include <utility>

namespace sortie::client {

RoutePreparation::RoutePreparation(RouteDocument *document, QObject *parent)
    : QObject(parent)
    , m_document(document)
{
    // The uploader only ever gets the open document's route: it is checked by the analyzer's
    // report, every rule included (terrain, and those other libraries add).
    m_uploader.setValidator([this](const mission::Route &) {
        m_document->analyzer()->recomputeNow();
        return m_document->analyzer()->validation();
    });
    connect(&m_uploader, &MissionUploader::stateChanged, this, [this] {
        if (m_uploader.state() != MissionUploader::State::AwaitingConfirmation)
            m_uploadAfterSave = false;
    });
    connect(&m_uploader, &MissionUploader::messageChanged, this, [this] { setMessage(m_uploader.message()); });
    connect(&m_uploader, &MissionUploader::uploaded, this, [this] { emit uploaded(m_uploadTarget); });
    // A preview shows one route for one vehicle: an edit or another vehicle makes it stale.
    const auto stale = [this] {
        ++m_run;
        setPreview({}, false);
        if (std::exchange(m_processing, false))
            emit processingChanged();
    };
    connect(m_document->undoStack(), &QUndoStack::indexChanged, this, stale);
    connect(m_document, &RouteDocument::loaded, this, stale);
}

void RoutePreparation::setFleet(VehicleFleet *fleet)
{
    if (fleet == m_fleet)
        return;
    m_fleet = fleet;
    m_uploader.setCommandLog(fleet ? fleet->commandLog() : nullptr);
    emit fleetChanged();
}

void RoutePreparation::setVehicleId(const QString &vehicleId)
{
    if (vehicleId == m_vehicleId)
        return;
    m_vehicleId = vehicleId;
    ++m_run;
    setPreview({}, false);
    if (std::exchange(m_processing, false))
        emit processingChanged();
    emit vehicleIdChanged();
}

vehicle::Vehicle *RoutePreparation::chosen(const QString &doing)
{
    vehicle::Vehicle *target = m_fleet && !m_vehicleId.isEmpty() ? m_fleet->vehicle(m_vehicleId) : nullptr;
    if (!target)
        setMessage(tr("Choose the vehicle to %1 for.").arg(doing));
    return target;
}

void RoutePreparation::process()
{
    vehicle::Vehicle *target = chosen(tr("process the route"));
    if (!target)
        return;
    vehicle::VehicleLink *link = target->link();
    if (!link)
        return setMessage(tr("%1 has no link.").arg(target->name()));
    const int run = ++m_run;
    const QString name = target->name();
    m_processing = true;
    emit processingChanged();
    setMessage(tr("Processing for %1…").arg(name));
    link->prepareMission(m_document->route(), [this, guard = QPointer(this), run, name](const vehicle::CommandResult &result,
                                                                                         const vehicle::PreparedMission &prepared) {
        if (!guard || run != m_run)
            return;
        m_processing = false;
        emit processingChanged();
        if (!result.ok) {
            setPreview({{}, {result.message}, {}}, false);
            return setMessage(tr("Not processed for %1: %2").arg(name, result.message));
        }
        setPreview(prepared, true);
        setMessage(tr("Processed for %1: %n waypoint(s) to fly.", nullptr, int(prepared.items.size())).arg(name));
    });
}

void RoutePreparation::upload()
{
    vehicle::Vehicle *target = chosen(tr("upload"));
    if (!target)
        return;
    if (m_uploader.isBusy())
        return setMessage(m_uploader.state() == MissionUploader::State::AwaitingConfirmation
                              ? tr("An upload is waiting for your answer.")
                              : tr("Wait until %1 is done.").arg(m_uploader.activity().toLower()));
    m_uploadTarget = m_vehicleId;
    m_uploader.start(m_document->route(), target, m_document->isModified());
}

void RoutePreparation::saveAndUpload()
{
    if (m_uploader.state() != MissionUploader::State::AwaitingConfirmation)
        return;
    m_uploadAfterSave = true;
    emit saveRequested();
}

void RoutePreparation::routeSaved()
{
    if (!m_uploadAfterSave)
        return;
    m_uploadAfterSave = false;
    // What goes up is the route as saved, checked again (edits made while asking are not skipped).
    m_uploader.confirm(m_document->route(), m_document->isModified());
}

void RoutePreparation::setMessage(const QString &message)
{
    if (message == m_message)
        return;
    m_message = message;
    emit messageChanged();
}

void RoutePreparation::setPreview(vehicle::PreparedMission preview, bool has)
{
    if (!has && !m_hasPreview && preview.notices.isEmpty() && m_preview.notices.isEmpty())
        return;
    m_preview = std::move(preview);
    m_hasPreview = has;
    emit previewChanged();
}

} // namespace sortie::client
