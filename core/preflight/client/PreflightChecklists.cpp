#include "PreflightChecklists.h"

#include "FleetRoutes.h"
#include "PreflightLog.h"
#include "RouteAnalyzer.h"
#include "RouteDocument.h"
#include "RoutePreparation.h"
#include "Vehicle.h"
#include "VehicleFleet.h"

#include <QDir>
#include <QFile>

#include <cmath>

namespace sortie::preflight {

using client::CommandPolicy;
using vehicle::TelemetryField;
using vehicle::Vehicle;

namespace {
// A vehicle type as a file name: "Fixed Wing" -> "fixed_wing"; nothing else of it reaches the path.
QString typeFileName(const QString &type)
{
    QString name;
    for (const QChar c : type.trimmed().toLower())
        name += c.isLetterOrNumber() && c.unicode() < 128 ? c : QLatin1Char('_');
    return name.isEmpty() ? QString() : name + QStringLiteral(".json");
}

std::optional<double> reported(const Vehicle *v, TelemetryField field)
{
    const auto sample = v->last(field);
    if (!sample || !std::isfinite(sample->value))
        return std::nullopt;
    return sample->value;
}

// Armed, and not known to be on the ground: pre-flight is behind it.
bool airborne(const Vehicle *v)
{
    if (!v->armed())
        return false;
    const auto agl = reported(v, TelemetryField::AltitudeAgl);
    return !agl || v->isStale(TelemetryField::AltitudeAgl) || *agl >= 0.5;
}
} // namespace

PreflightChecklists::PreflightChecklists(client::VehicleFleet *fleet, client::FleetRoutes *routes, client::RouteDocument *document,
                                         client::RoutePreparation *preparation, QString folder, QObject *parent)
    : QObject(parent)
    , m_fleet(fleet)
    , m_routes(routes)
    , m_document(document)
    , m_preparation(preparation)
    , m_folder(std::move(folder))
{
    if (m_fleet)
        m_fleet->commands()->setGate(this);
    if (m_routes) {
        connect(m_routes, &QAbstractItemModel::dataChanged, this, &PreflightChecklists::refreshAll);
        connect(m_routes, &QAbstractItemModel::rowsInserted, this, &PreflightChecklists::refreshAll);
        connect(m_routes, &QAbstractItemModel::rowsRemoved, this, &PreflightChecklists::refreshAll);
        connect(m_routes, &QAbstractItemModel::modelReset, this, &PreflightChecklists::refreshAll);
    }
    if (m_document) {
        connect(m_document->analyzer(), &mission::RouteAnalyzer::validationChanged, this, &PreflightChecklists::refreshAll);
        connect(m_document->analyzer(), &mission::RouteAnalyzer::pendingChanged, this, &PreflightChecklists::refreshAll);
    }
    if (m_preparation)
        connect(m_preparation, &client::RoutePreparation::vehicleIdChanged, this, &PreflightChecklists::refreshAll);
}

PreflightChecklists::~PreflightChecklists()
{
    if (m_fleet)
        m_fleet->commands()->setGate(nullptr);
}

VehicleChecklist *PreflightChecklists::checklistFor(Vehicle *vehicle)
{
    if (!vehicle)
        return nullptr;
    if (const auto it = m_lists.find(vehicle); it != m_lists.end())
        return it->second;

    Checklist checklist = defaultChecklist();
    QString source, error;
    const QDir dir(m_folder);
    for (const QString &name : {typeFileName(vehicle->identity().type), QStringLiteral("default.json")}) {
        if (m_folder.isEmpty() || name.isEmpty() || !dir.exists(name))
            continue;
        const QString path = dir.filePath(name);
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) {
            error = tr("%1 cannot be read: %2").arg(QDir::toNativeSeparators(path), file.errorString());
            break;
        }
        auto read = readChecklist(file.readAll());
        if (!read) {
            error = read.error().withFile(QDir::toNativeSeparators(path)).toString();
            qCWarning(lcPreflight) << "checklist not used:" << error;
            break;
        }
        checklist = std::move(read).value();
        if (checklist.name.isEmpty())
            checklist.name = QFileInfo(path).completeBaseName();
        source = path;
        break;
    }
    auto *list = new VehicleChecklist(vehicle, std::move(checklist), source, error,
                                      [this](const Vehicle *v) { return factsOf(v); }, this);
    m_lists.emplace(vehicle, list);
    connect(vehicle, &QObject::destroyed, list, [this, vehicle, list] {
        m_lists.erase(vehicle);
        list->deleteLater();
    });
    qCInfo(lcPreflight) << vehicle->name() << "checked by" << (source.isEmpty() ? QStringLiteral("Sortie's default checklist") : source);
    return list;
}

void PreflightChecklists::reload()
{
    auto old = std::move(m_lists);
    m_lists.clear();
    for (auto &[vehicle, list] : old) {
        disconnect(vehicle, nullptr, list, nullptr);
        list->deleteLater();
    }
    ++m_revision;
    qCInfo(lcPreflight) << "checklists read again from" << m_folder;
    emit reloaded();
}

QStringList PreflightChecklists::blockers(CommandPolicy::Command command, const Vehicle *vehicle)
{
    if (!vehicle || airborne(vehicle))
        return {};
    Gate gate;
    switch (command) {
    case CommandPolicy::Command::Arm:
    case CommandPolicy::Command::TakeOff: gate = GateArm; break;
    case CommandPolicy::Command::Auto: gate = GateAuto; break;
    default: return {};
    }
    VehicleChecklist *list = checklistFor(const_cast<Vehicle *>(vehicle));
    list->refresh();
    const QStringList held = list->blockers(gate);
    if (!held.isEmpty())
        qCDebug(lcPreflight).noquote() << vehicle->name() << (gate == GateArm ? "arm" : "auto") << "held back:" << held.join(QStringLiteral("; "));
    return held;
}

PreflightFacts PreflightChecklists::factsOf(const Vehicle *v) const
{
    PreflightFacts facts;
    facts.linkUp = v->isConnected() && !v->isStale();
    facts.gpsFix = reported(v, TelemetryField::GpsFix);
    facts.satellites = reported(v, TelemetryField::Satellites);
    if (const auto remaining = reported(v, TelemetryField::BatteryRemaining))
        facts.batteryPercent = *remaining * 100;
    facts.homeReportable = v->link() && v->link()->capabilities().testFlag(vehicle::VehicleLink::HomePosition);
    facts.homeSet = v->home().isValid();
    facts.cameraPresent = !v->videoStreamUri().isEmpty();

    const QString id = v->fleetId();
    if (m_routes) {
        // On board and nothing else planned for it: the route it holds is the one planned.
        for (const client::FleetRouteState state : m_routes->statesOf(id)) {
            if (state == client::FleetRouteState::Planned) {
                facts.routeOnBoard = false;
                break;
            }
            facts.routeOnBoard = true;
        }
    }
    if (m_document && m_preparation && m_preparation->vehicleId() == id && !m_document->analyzer()->isPending())
        facts.routeErrors = m_document->analyzer()->errorCount();
    return facts;
}

void PreflightChecklists::refreshAll()
{
    for (auto &[vehicle, list] : m_lists)
        list->refresh();
}

} // namespace sortie::preflight
