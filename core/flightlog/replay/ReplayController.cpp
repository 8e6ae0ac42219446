#include "ReplayController.h"

#include "FlightLogExport.h"
#include "FlightLogLog.h"

#include <QDateTime>
#include <QMetaEnum>
#include <QSaveFile>

#include <utility>

#include <cmath>
#include <numbers>

namespace sortie::flightlog {

using vehicle::Vehicle;
using vehicle::VehicleLink;

// --- ReplayFleet -----------------------------------------------------------------------------

Vehicle *ReplayFleet::vehicleAt(int row) const
{
    return row >= 0 && row < count() ? m_vehicles[size_t(row)] : nullptr;
}

void ReplayFleet::reset(std::vector<Vehicle *> vehicles)
{
    beginResetModel();
    for (const auto &c : m_connections)
        disconnect(c);
    m_connections.clear();
    m_vehicles = std::move(vehicles);
    for (size_t row = 0; row < m_vehicles.size(); ++row) {
        auto changed = [this, row] { emit dataChanged(index(int(row)), index(int(row))); };
        m_connections.push_back(connect(m_vehicles[row], &Vehicle::telemetryChanged, this, changed));
        m_connections.push_back(connect(m_vehicles[row], &Vehicle::linkStateChanged, this, changed));
    }
    endResetModel();
    emit countChanged();
}

int ReplayFleet::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QHash<int, QByteArray> ReplayFleet::roleNames() const
{
    return {{VehicleIdRole, "vehicleId"}, {NameRole, "name"}, {ProtocolRole, "protocol"}, {LinkStateRole, "linkState"},
            {StaleRole, "stale"}, {LatitudeRole, "latitude"}, {LongitudeRole, "longitude"}, {HeadingRole, "heading"},
            {HomeLatitudeRole, "homeLatitude"}, {HomeLongitudeRole, "homeLongitude"}, {AltitudeAglRole, "altitudeAgl"},
            {GroundSpeedRole, "groundSpeed"}, {ModeRole, "mode"}, {ArmedRole, "armed"}, {BatteryRole, "battery"},
            {VehicleRole, "vehicle"}, {ReplayRole, "replay"}};
}

QVariant ReplayFleet::data(const QModelIndex &index, int role) const
{
    const Vehicle *v = vehicleAt(index.row());
    if (!v || index.parent().isValid())
        return {};
    auto finite = [](double value) { return std::isfinite(value) ? QVariant(value) : QVariant(); };
    switch (role) {
    case VehicleIdRole: return v->fleetId();
    case NameRole:
    case Qt::DisplayRole: return v->name();
    case ProtocolRole: return v->protocol();
    case LinkStateRole: return QString::fromLatin1(QMetaEnum::fromType<VehicleLink::State>().valueToKey(int(v->linkState())));
    case StaleRole: return !v->isConnected();
    case LatitudeRole: return v->position().isValid() ? QVariant(v->position().latitude()) : QVariant();
    case LongitudeRole: return v->position().isValid() ? QVariant(v->position().longitude()) : QVariant();
    case HeadingRole: return finite(v->heading());
    case HomeLatitudeRole: return v->home().isValid() ? QVariant(v->home().latitude()) : QVariant();
    case HomeLongitudeRole: return v->home().isValid() ? QVariant(v->home().longitude()) : QVariant();
    case AltitudeAglRole: return finite(v->altitudeAgl());
    case GroundSpeedRole: return finite(v->groundSpeed());
    case ModeRole: return v->mode();
    case ArmedRole: return v->armed();
    case BatteryRole: return finite(v->batteryRemaining());
    case VehicleRole: return QVariant::fromValue(static_cast<QObject *>(vehicleAt(index.row())));
    case ReplayRole: return true;
    default: return {};
    }
}

// --- ReplayController ------------------------------------------------------------------------

ReplayController::ReplayController(QObject *parent)
    : QObject(parent)
{
    m_timer.setInterval(16); // display rate; the position follows the wall clock, not the tick count
    connect(&m_timer, &QTimer::timeout, this, &ReplayController::tick);
}

ReplayController::~ReplayController()
{
    stopHistoryFill();
    m_fleet.reset({});
}

Vehicle *ReplayController::vehicle(int index) const
{
    return index >= 0 && size_t(index) < m_vehicles.size() ? m_vehicles[size_t(index)].vehicle.get() : nullptr;
}

void ReplayController::setError(const QString &error)
{
    if (error == m_error)
        return;
    m_error = error;
    emit errorChanged();
}

bool ReplayController::open(const QString &pathOrUrl)
{
    const QString path = pathOrUrl.startsWith(QLatin1String("file:")) ? QUrl(pathOrUrl).toLocalFile() : pathOrUrl;
    QString error;
    auto log = FlightLog::open(path, &error);
    if (!log) {
        setError(error);
        return false;
    }
    open(std::move(log));
    return true;
}

void ReplayController::open(std::unique_ptr<FlightLog> log)
{
    close();
    setError({});
    m_log = std::move(log);
    for (size_t i = 0; i < m_log->vehicles().size(); ++i) {
        const FlightLog::Vehicle &recorded = m_log->vehicles()[i];
        Replayed r;
        vehicle::VehicleIdentity identity = recorded.identity;
        if (identity.name.isEmpty())
            identity.name = recorded.name();
        r.link = std::make_unique<ReplayVehicleLink>(identity);
        r.vehicle = std::make_unique<Vehicle>(r.link.get(), this);
        r.vehicle->setStaleAfter(std::numeric_limits<int>::max() / 2); // paused is not silent
        m_vehicles.push_back(std::move(r));
    }
    std::vector<Vehicle *> vehicles;
    for (const Replayed &r : m_vehicles)
        vehicles.push_back(r.vehicle.get());
    m_fleet.reset(vehicles);
    m_events.reset(m_log.get());
    m_position = m_log->start();
    showAt(m_position);
    startHistoryFill();
    qCInfo(lcFlightLog) << "replaying" << m_log->path() << m_vehicles.size() << "vehicles";
    emit loadedChanged();
    emit positionChanged();
}

void ReplayController::startHistoryFill()
{
    std::vector<size_t> capacities;
    for (const Replayed &r : m_vehicles)
        capacities.push_back(r.vehicle->history().capacityPerField());
    auto cancelled = std::make_shared<std::atomic_bool>(false);
    m_cancelHistory = cancelled;
    const quint64 generation = ++m_generation;
    std::shared_ptr<const FlightLog> log = m_log;
    m_historyThread.reset(QThread::create([this, log, cancelled, capacities, generation] {
        QElapsedTimer took;
        took.start();
        // Built here whole, so the GUI thread only swaps them in.
        auto histories = std::make_shared<std::vector<vehicle::TelemetryStore>>();
        for (size_t i = 0; i < capacities.size(); ++i) {
            const auto series = log->thinnedSeries(int(i), capacities[i], cancelled.get());
            if (!series)
                return; // closed meanwhile
            histories->emplace_back(capacities[i]);
            histories->back().ingest(*series);
        }
        qCDebug(lcFlightLog) << "replay histories decoded in" << took.elapsed() << "ms";
        // close() waits for this thread, so `this` outlives the call; a result of an earlier log
        // is recognised by its generation.
        QMetaObject::invokeMethod(this, [this, generation, histories] { applyHistories(generation, *histories); }, Qt::QueuedConnection);
    }));
    m_historyThread->setObjectName(QStringLiteral("replay-history"));
    m_historyThread->start(QThread::LowPriority);
}

void ReplayController::stopHistoryFill()
{
    if (m_cancelHistory)
        m_cancelHistory->store(true);
    if (m_historyThread)
        m_historyThread->wait();
    m_historyThread.reset();
    m_cancelHistory.reset();
}

void ReplayController::applyHistories(quint64 generation, std::vector<vehicle::TelemetryStore> &histories)
{
    if (generation != m_generation || !m_log || histories.size() != m_vehicles.size())
        return;
    for (size_t i = 0; i < histories.size(); ++i)
        m_vehicles[i].vehicle->replaceHistory(std::move(histories[i]));
    m_historyLoaded = true;
    emit historyLoadedChanged();
}

void ReplayController::close()
{
    if (!m_log)
        return;
    pause();
    stopHistoryFill();
    ++m_generation;
    const bool hadHistory = std::exchange(m_historyLoaded, false);
    m_fleet.reset({});
    m_events.reset(nullptr);
    m_vehicles.clear();
    m_log.reset();
    m_position = 0;
    emit loadedChanged();
    emit positionChanged();
    if (hadHistory)
        emit historyLoadedChanged();
}

double ReplayController::progress() const
{
    if (!m_log || m_log->end() <= m_log->start())
        return 0;
    return double(m_position - m_log->start()) / double(m_log->end() - m_log->start());
}

QString ReplayController::positionText() const
{
    if (!m_log)
        return {};
    const qint64 s = (m_position - m_log->start()) / 1000;
    return QStringLiteral("%1  (+%2:%3:%4)")
        .arg(QDateTime::fromMSecsSinceEpoch(m_position, Qt::UTC).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss 'UTC'")))
        .arg(s / 3600).arg(s / 60 % 60, 2, 10, QLatin1Char('0')).arg(s % 60, 2, 10, QLatin1Char('0'));
}

QString ReplayController::spanText() const
{
    if (!m_log)
        return {};
    const qint64 s = (m_log->end() - m_log->start()) / 1000;
    const QString duration = QStringLiteral("%1:%2:%3").arg(s / 3600).arg(s / 60 % 60, 2, 10, QLatin1Char('0')).arg(s % 60, 2, 10, QLatin1Char('0'));
    return m_vehicles.size() == 1 ? tr("%1 of 1 vehicle").arg(duration) : tr("%1 of %2 vehicles").arg(duration).arg(m_vehicles.size());
}

void ReplayController::play()
{
    if (!m_log || m_timer.isActive())
        return;
    if (m_position >= m_log->end())
        seek(m_log->start()); // from the start again
    m_wall.start();
    m_timer.start();
    emit playingChanged();
}

void ReplayController::pause()
{
    if (!m_timer.isActive())
        return;
    m_timer.stop();
    emit playingChanged();
}

void ReplayController::setSpeed(double speed)
{
    speed = std::clamp(speed, kMinSpeed, kMaxSpeed);
    if (speed == m_speed)
        return;
    m_speed = speed;
    emit speedChanged();
}

void ReplayController::tick()
{
    advance(m_wall.restart());
}

void ReplayController::advance(qint64 ms)
{
    if (!m_log)
        return;
    const qint64 target = std::min<qint64>(m_log->end(), m_position + qint64(std::llround(double(ms) * m_speed)));
    playTo(target);
    if (m_position >= m_log->end())
        pause();
}

void ReplayController::seek(qint64 time)
{
    if (!m_log)
        return;
    time = std::clamp<qint64>(time, m_log->start(), m_log->end());
    showAt(time);
    if (m_timer.isActive())
        m_wall.restart();
    emit seeked();
    emit positionChanged();
}

void ReplayController::setProgress(double fraction)
{
    if (!m_log)
        return;
    seek(m_log->start() + qint64(std::llround(std::clamp(fraction, 0.0, 1.0) * double(m_log->end() - m_log->start()))));
}

void ReplayController::jumpToEvent(int row)
{
    if (const FlightLog::Event *e = m_events.eventAt(row))
        seek(e->time);
}

void ReplayController::nextEvent()
{
    const int row = m_events.nextAfter(m_position);
    if (row >= 0)
        jumpToEvent(row);
}

void ReplayController::previousEvent()
{
    const int row = m_events.lastBefore(m_position);
    if (row >= 0)
        jumpToEvent(row);
}

QString ReplayController::exportTracks(const QString &format, const QUrl &file) const
{
    if (!m_log)
        return tr("No log is open.");
    const auto f = exportFormatFromName(format);
    if (!f)
        return tr("\"%1\" is not an export format (gpx, kml or csv).").arg(format);
    QSaveFile out(file.isLocalFile() ? file.toLocalFile() : file.toString());
    QString error;
    if (!out.open(QIODevice::WriteOnly) || !exportLog(*m_log, *f, {}, &out, &error) || !out.commit())
        return tr("%1 could not be written: %2").arg(out.fileName(), error.isEmpty() ? out.errorString() : error);
    return {};
}

void ReplayController::showAt(qint64 time)
{
    for (size_t i = 0; i < m_vehicles.size(); ++i)
        m_vehicles[i].link->deliver(m_log->stateAt(int(i), time));
    m_position = time;
    applyEventsAndMissions(time);
}

void ReplayController::playTo(qint64 time)
{
    if (time <= m_position)
        return;
    for (size_t i = 0; i < m_vehicles.size(); ++i)
        m_vehicles[i].link->deliver(m_log->updatesBetween(int(i), m_position, time));
    m_position = time;
    applyEventsAndMissions(time);
    emit positionChanged();
}

void ReplayController::applyEventsAndMissions(qint64 time)
{
    const QMetaEnum states = QMetaEnum::fromType<VehicleLink::State>();
    for (size_t i = 0; i < m_vehicles.size(); ++i) {
        VehicleLink::State state = VehicleLink::State::Connected;
        for (const FlightLog::Event &e : m_log->events()) {
            if (e.time > time)
                break;
            if (e.vehicle == int(i) && e.kind == QLatin1String("link")) {
                bool ok = false;
                const int value = states.keyToValue(e.text.toLatin1().constData(), &ok);
                if (ok)
                    state = VehicleLink::State(value);
            }
        }
        m_vehicles[i].link->setState(state);
        const FlightLog::Vehicle &recorded = m_log->vehicles()[i];
        std::vector<vehicle::MissionItem> mission;
        for (const FlightLog::Mission &m : recorded.missions) {
            if (m.time <= time)
                mission = m.items;
        }
        m_vehicles[i].vehicle->setMission(std::move(mission));
    }
}

} // namespace sortie::flightlog
