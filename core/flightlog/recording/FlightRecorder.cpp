#include "FlightRecorder.h"

#include "FlightLogLog.h"
#include "FlightLogSchema.h"
#include "PhotoEvents.h"
#include "PrivateFiles.h"

#include <QDateTime>
#include <QDir>
#include <QMetaEnum>

namespace sortie::flightlog {

using vehicle::TelemetryField;
using vehicle::Vehicle;
using vehicle::VehicleLink;

FlightRecorder::FlightRecorder(Options options, QObject *parent)
    : QObject(parent)
    , m_options(std::move(options))
{
    m_thread.setObjectName(QStringLiteral("flightlog-writer"));
    m_flushTimer.setInterval(std::max(50, m_options.flushIntervalMs));
    connect(&m_flushTimer, &QTimer::timeout, this, &FlightRecorder::flush);
}

FlightRecorder::~FlightRecorder()
{
    stop();
    disconnect(m_commands);
    for (const auto &r : m_recorded) {
        for (const auto &c : r->connections)
            disconnect(c);
        disconnect(r->telemetry);
    }
}

QString FlightRecorder::sessionPath(const QString &folder)
{
    const QString stamp = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss"));
    const QString first = QDir(folder).filePath(QStringLiteral("session-%1%2").arg(stamp, QLatin1String(schema::kSuffix)));
    if (!files::makePrivatePath(folder))
        return first; // the writer says why it cannot write there
    // Claimed with O_EXCL: two clients started in the same second each get a file of their own
    // ("-c2": never "-2", which names a log's second part).
    for (int n = 1; n <= 999; ++n) {
        const QString path = n == 1 ? first
                                    : QDir(folder).filePath(QStringLiteral("session-%1-c%2%3").arg(stamp).arg(n).arg(QLatin1String(schema::kSuffix)));
        if (files::claimNewFile(path))
            return path;
    }
    return first;
}

bool FlightRecorder::start(QString *error)
{
    if (m_thread.isRunning())
        return true;
    m_writer = new FlightLogWriter(m_options.path, m_options.limits);
    m_writer->moveToThread(&m_thread);
    connect(m_writer, &FlightLogWriter::errorOccurred, this, [this](const QString &message) {
        m_error = message;
        emit errorChanged();
    });
    connect(m_writer, &FlightLogWriter::rotated, this, &FlightRecorder::pathChanged);
    m_thread.start();
    bool ok = false;
    QString why;
    FlightLogWriter *writer = m_writer;
    QMetaObject::invokeMethod(writer, [writer, &ok, &why] { ok = writer->open(&why); }, Qt::BlockingQueuedConnection);
    if (!ok) {
        QMetaObject::invokeMethod(writer, [writer] { delete writer; }, Qt::BlockingQueuedConnection);
        m_writer = nullptr;
        m_thread.quit();
        m_thread.wait();
        m_error = tr("The flight log %1 cannot be written: %2").arg(m_options.path, why);
        emit errorChanged();
        if (error)
            *error = m_error;
        return false;
    }
    if (m_options.limits.maxFolderBytes > 0)
        FlightLogWriter::pruneFolder(QFileInfo(m_options.path).absolutePath(), m_options.limits.maxFolderBytes, m_options.path);
    m_flushTimer.start();
    recordEvent(nullptr, QStringLiteral("session"), tr("Recording started"));
    emit recordingChanged();
    emit pathChanged();
    return true;
}

void FlightRecorder::stop()
{
    if (!m_thread.isRunning())
        return;
    recordEvent(nullptr, QStringLiteral("session"), tr("Recording stopped"));
    flush();
    m_flushTimer.stop();
    FlightLogWriter *writer = m_writer;
    FlightLogWriter::Stats last;
    QMetaObject::invokeMethod(writer, [writer, &last] {
        last = writer->stats();
        delete writer; // closes the file
    }, Qt::BlockingQueuedConnection);
    m_lastStats = last;
    m_writer = nullptr;
    m_thread.quit();
    m_thread.wait();
    emit recordingChanged();
}

QString FlightRecorder::path() const
{
    return m_writer ? m_writer->currentPath() : m_options.path;
}

QString FlightRecorder::folder() const
{
    return QFileInfo(m_options.path).absolutePath();
}

void FlightRecorder::setLimits(RecordingLimits limits)
{
    if (limits.maxFileBytes == m_options.limits.maxFileBytes && limits.maxFolderBytes == m_options.limits.maxFolderBytes)
        return;
    m_options.limits = limits;
    if (FlightLogWriter *writer = m_writer) {
        writer->setLimits(limits);
        QMetaObject::invokeMethod(writer, [writer] { writer->enforceLimits(); }, Qt::QueuedConnection);
    }
    emit limitsChanged();
}

FlightLogWriter::Stats FlightRecorder::stats() const
{
    return m_writer ? m_writer->stats() : m_lastStats;
}

int64_t FlightRecorder::now()
{
    return QDateTime::currentMSecsSinceEpoch();
}

FlightRecorder::Recorded *FlightRecorder::find(const Vehicle *vehicle)
{
    for (const auto &r : m_recorded) {
        if (r->vehicle == vehicle)
            return r.get();
    }
    return nullptr;
}

void FlightRecorder::addVehicle(Vehicle *vehicle)
{
    if (!vehicle || find(vehicle) || vehicle->protocol() == QLatin1String("Replay"))
        return; // a replay is a record already
    auto owned = std::make_unique<Recorded>();
    Recorded &r = *owned;
    r.vehicle = vehicle;
    static int anonymous = 0;
    r.key = vehicle->protocol() + QLatin1Char(':') + (vehicle->id().isEmpty() ? QStringLiteral("#%1").arg(++anonymous) : vehicle->id());
    r.pending.vehicleKey = r.key;
    r.slot.fill(-1);
    m_recorded.push_back(std::move(owned));

    auto identity = [this, &r] {
        vehicle::VehicleIdentity id = r.vehicle->identity();
        if (id.protocol.isEmpty())
            id.protocol = r.vehicle->protocol();
        m_chunk.vehicles.push_back({r.key, id});
    };
    identity();
    if (!vehicle->mission().empty())
        m_chunk.missions.push_back({r.key, now(), vehicle->mission()});
    if (VehicleLink *link = vehicle->link()) {
        r.telemetry = connect(link, &VehicleLink::telemetryReceived, this,
                              [this, &r](const vehicle::TelemetryBatch &batch) { gather(r, batch); });
    }
    r.connections.push_back(connect(vehicle, &Vehicle::identityChanged, this, identity));
    r.connections.push_back(connect(vehicle, &Vehicle::linkStateChanged, this, [this, &r] {
        const char *state = QMetaEnum::fromType<VehicleLink::State>().valueToKey(int(r.vehicle->linkState()));
        writeEvent(r, QStringLiteral("link"), QString::fromLatin1(state));
    }));
    r.connections.push_back(connect(vehicle, &Vehicle::missionChanged, this, [this, &r] {
        m_chunk.missions.push_back({r.key, vehicleTime(r), r.vehicle->mission()});
        const size_t n = r.vehicle->mission().size();
        writeEvent(r, QStringLiteral("upload"), n == 1 ? tr("Route of 1 waypoint") : tr("Route of %1 waypoints").arg(n));
    }));
    r.connections.push_back(connect(vehicle, &Vehicle::photoTaken, this, [this, &r](const vehicle::CameraPhoto &photo) {
        m_chunk.events.push_back({r.key, photo.time > 0 ? photo.time : vehicleTime(r), QString::fromLatin1(kPhotoEventKind), photoEventText(photo), -1});
    }));
    r.connections.push_back(connect(vehicle, &QObject::destroyed, this, [this, raw = vehicle] {
        for (auto it = m_recorded.begin(); it != m_recorded.end(); ++it) {
            if (!(*it)->vehicle || (*it)->vehicle == raw) {
                // Keep what it sent before going.
                if (!(*it)->pending.fields.empty())
                    m_chunk.samples.push_back(std::move((*it)->pending));
                for (const auto &c : (*it)->connections)
                    disconnect(c);
                disconnect((*it)->telemetry);
                m_recorded.erase(it);
                return;
            }
        }
    }));
    writeEvent(r, QStringLiteral("link"), QString::fromLatin1(QMetaEnum::fromType<VehicleLink::State>().valueToKey(int(vehicle->linkState()))));
}

void FlightRecorder::removeVehicle(Vehicle *vehicle)
{
    for (auto it = m_recorded.begin(); it != m_recorded.end(); ++it) {
        if ((*it)->vehicle == vehicle) {
            if (!(*it)->pending.fields.empty())
                m_chunk.samples.push_back(std::move((*it)->pending));
            for (const auto &c : (*it)->connections)
                disconnect(c);
            disconnect((*it)->telemetry);
            m_recorded.erase(it);
            return;
        }
    }
}

FlightRecorder::Recorded *FlightRecorder::findNamed(const QString &name)
{
    for (const auto &r : m_recorded) {
        if (r->vehicle && r->vehicle->name() == name)
            return r.get();
    }
    return nullptr;
}

void FlightRecorder::followCommands(vehicle::CommandLog *log)
{
    disconnect(m_commands);
    if (log)
        m_commands = connect(log, &vehicle::CommandLog::finished, this, &FlightRecorder::recordCommand);
}

void FlightRecorder::recordCommand(const vehicle::CommandLog::Entry &entry)
{
    const Recorded *r = findNamed(entry.vehicle);
    if (!r)
        return;
    // The command as the log words it ("takeoff to 20 m"), with the reason when it did not succeed.
    const QString text = entry.result.isEmpty() ? entry.command : entry.command + QStringLiteral(": ") + entry.result;
    if (entry.status == vehicle::CommandLog::Status::Alert)
        writeEvent(*r, QStringLiteral("alert"), entry.command);
    else
        writeEvent(*r, QStringLiteral("command"), text, entry.status == vehicle::CommandLog::Status::Done ? 1 : 0);
}

void FlightRecorder::recordEvent(Vehicle *vehicle, const QString &kind, const QString &text, int ok)
{
    const Recorded *r = find(vehicle);
    m_chunk.events.push_back({r ? r->key : QString(), r ? vehicleTime(*r) : now(), kind, text, ok});
}

void FlightRecorder::writeEvent(const Recorded &r, const QString &kind, const QString &text, int ok)
{
    m_chunk.events.push_back({r.key, vehicleTime(r), kind, text, ok});
}

void FlightRecorder::gather(Recorded &r, const vehicle::TelemetryBatch &batch)
{
    if (!batch.empty())
        r.clockOffset = batch.back().time - now();
    for (const vehicle::TelemetryUpdate &u : batch) {
        int &slot = r.slot[size_t(u.field)];
        if (slot < 0) {
            slot = int(r.pending.fields.size());
            r.pending.fields.push_back({u.field, {}});
        }
        r.pending.fields[size_t(slot)].samples.push_back({u.time, u.value});
        // Arming and mode changes are events of their own: the timeline jumps to them.
        if (u.field == TelemetryField::Armed && u.value != r.armed) {
            if (!std::isnan(r.armed) || u.value != 0)
                m_chunk.events.push_back({r.key, u.time, u.value != 0 ? QStringLiteral("armed") : QStringLiteral("disarmed"),
                                          u.value != 0 ? tr("Armed") : tr("Disarmed"), -1});
            r.armed = u.value;
        } else if (u.field == TelemetryField::Mode && u.value != r.mode) {
            const std::string_view name = vehicle::modeName(vehicle::FlightMode(int(u.value)));
            m_chunk.events.push_back({r.key, u.time, QStringLiteral("mode"), QString::fromLatin1(name.data(), qsizetype(name.size())), -1});
            r.mode = u.value;
        }
    }
}

void FlightRecorder::flush()
{
    if (!m_writer)
        return;
    for (const auto &r : m_recorded) {
        if (r->pending.fields.empty())
            continue;
        m_chunk.samples.push_back(std::move(r->pending));
        r->pending = RecordedSamples{r->key, {}};
        r->slot.fill(-1);
    }
    if (m_chunk.empty())
        return;
    auto chunk = std::make_shared<RecordingChunk>(std::move(m_chunk));
    m_chunk = RecordingChunk{};
    FlightLogWriter *writer = m_writer;
    QMetaObject::invokeMethod(writer, [writer, chunk] { writer->write(*chunk); }, Qt::QueuedConnection);
}

} // namespace sortie::flightlog
