#include "FlightLog.h"

#include "FlightLogLog.h"
#include "FlightLogSchema.h"
#include "OutsideDatabase.h"

#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QHash>
#include <QSqlError>
#include <QSqlQuery>
#include <QUuid>

#include <algorithm>
#include <optional>

namespace sortie::flightlog {

using vehicle::TelemetryBatch;
using vehicle::TelemetryField;
using vehicle::TelemetrySample;
using vehicle::TelemetryUpdate;

namespace {

QString timeText(int64_t ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz 'UTC'"));
}

// The connection is removed when the last query on it is gone.
class Connection
{
public:
    explicit Connection(const QString &path, bool readOnly, QString *error)
        : m_name(QStringLiteral("flightlog-reader-") + QUuid::createUuid().toString(QUuid::WithoutBraces))
    {
        m_db = schema::open(path, m_name, readOnly, error);
    }
    ~Connection()
    {
        m_db.close();
        m_db = QSqlDatabase();
        QSqlDatabase::removeDatabase(m_name);
    }
    QSqlDatabase &db() { return m_db; }

private:
    QString m_name;
    QSqlDatabase m_db;
};

quint32 bigEndian32(const QByteArray &b, int at)
{
    return quint32(uchar(b[at])) << 24 | quint32(uchar(b[at + 1])) << 16 | quint32(uchar(b[at + 2])) << 8 | quint32(uchar(b[at + 3]));
}

// SQLite's header (its file format, "The Database Header") says the file holds more pages than it
// does: a log cut short. The size is believed only when the change counter (offset 24) equals the
// version-valid-for number (offset 92).
bool cutShort(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return false;
    const QByteArray h = f.read(100);
    if (h.size() < 100 || !h.startsWith("SQLite format 3"))
        return false;
    const quint32 pageSize = (quint32(uchar(h[16])) << 8 | uchar(h[17])) == 1 ? 65536 : (quint32(uchar(h[16])) << 8 | uchar(h[17]));
    const quint32 pages = bigEndian32(h, 28);
    return pages && bigEndian32(h, 24) == bigEndian32(h, 92) && qint64(pages) * pageSize > f.size();
}

// A log the recorder did not close (its -wal beside it) or one cut short is read from a copy in a
// private folder of its own: there SQLite applies the journal's committed transactions, and a copy
// cut short has its header's page count set aside (the version-valid-for number changed) so SQLite
// reads the pages that are there. The operator's file is never written.
std::optional<QString> readableCopy(const QString &path, QTemporaryDir &dir, QString *error)
{
    const QString wal = path + QStringLiteral("-wal");
    const bool recorderKilled = QFileInfo::exists(wal), shortened = cutShort(path);
    if (!recorderKilled && !shortened)
        return QString();
    const QString copy = dir.filePath(QStringLiteral("log.sortielog"));
    if (!dir.isValid() || !QFile::copy(path, copy) || (recorderKilled && !QFile::copy(wal, copy + QStringLiteral("-wal")))) {
        *error = QObject::tr("%1: cannot be opened: no private copy to recover it in (%2)").arg(path, dir.errorString());
        return std::nullopt;
    }
    QFile::setPermissions(copy, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
    QFile::setPermissions(copy + QStringLiteral("-wal"), QFileDevice::ReadOwner | QFileDevice::WriteOwner);
    if (shortened) {
        QFile f(copy);
        if (f.open(QIODevice::ReadWrite) && f.seek(24)) {
            QByteArray counter = f.read(4);
            if (counter.size() == 4 && f.seek(92)) {
                counter[3] = char(counter[3] ^ 1);
                f.write(counter);
            }
        }
    }
    qCInfo(lcFlightLog) << path << "read from a private copy:" << (recorderKilled ? "its recorder did not close it" : "it is cut short");
    return copy;
}

} // namespace

uint64_t FlightLog::Vehicle::sampleCount() const
{
    uint64_t n = 0;
    for (uint64_t c : counts)
        n += c;
    return n;
}

bool FlightLog::Vehicle::appendBlock(std::string data, std::string *error)
{
    const auto summary = TelemetryBlockCodec::summarize(data, error);
    if (!summary)
        return false;
    Block b{summary->t0, summary->t1, 0, std::move(data)};
    for (size_t f = 0; f < vehicle::kTelemetryFieldCount; ++f) {
        if (summary->counts[f]) {
            b.fields |= 1u << f;
            counts[f] += summary->counts[f];
        }
    }
    blocks.push_back(std::move(b));
    return true;
}

std::unique_ptr<FlightLog> FlightLog::open(const QString &path, QString *error)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = why;
        return nullptr;
    };
    if (!QFileInfo(path).isFile())
        return fail(QObject::tr("%1: no such file").arg(path));
    QTemporaryDir recovery;
    QString copyError;
    const std::optional<QString> copy = readableCopy(path, recovery, &copyError);
    if (!copy)
        return fail(copyError);
    QString why;
    Connection c(copy->isEmpty() ? path : *copy, copy->isEmpty(), &why);
    if (!c.db().isOpen())
        return fail(QObject::tr("%1: cannot be opened: %2").arg(path, why));
    QSqlQuery q(c.db());
    q.setForwardOnly(true);
    if (!q.exec(QStringLiteral("SELECT value FROM meta WHERE key = 'application'")) || !q.next()
        || q.value(0).toString() != QLatin1String(schema::kApplicationId)) {
        const QString detail = q.lastError().isValid() ? q.lastError().text() : QObject::tr("no Sortie flight log header");
        return fail(QObject::tr("%1 is not a Sortie flight log (%2)").arg(path, detail));
    }
    // Each part of a log is a table: a view (a recursive one never ends) or anything else is refused.
    if (!q.exec(QStringLiteral("SELECT name, type FROM sqlite_schema WHERE name IN ('meta', 'vehicles', 'blocks', 'events', 'missions')")))
        return fail(QObject::tr("%1 is not a Sortie flight log (%2)").arg(path, q.lastError().text()));
    while (q.next()) {
        if (q.value(1).toString() != QLatin1String("table"))
            return fail(QObject::tr("%1 is not a Sortie flight log (its %2 is a %3, not a table)").arg(path, q.value(0).toString(), q.value(1).toString()));
    }
    // The reason a bound of core/sqlite stopped a statement, or SQLite's.
    auto errorOf = [&c, &q] {
        const QString bound = sqlite::statementStopped(c.db());
        return bound.isEmpty() ? q.lastError().text() : QObject::tr("stopped: %1").arg(bound);
    };

    auto log = std::make_unique<FlightLog>();
    log->m_path = path;
    QHash<qint64, int> vehicleOf;
    auto stop = [&log](const QString &why) {
        if (log->m_stoppedAt.isEmpty())
            log->m_stoppedAt = why;
    };

    if (!q.exec(QStringLiteral("SELECT id, key, name, protocol, type, autopilot FROM vehicles ORDER BY id")))
        return fail(QObject::tr("%1: the vehicles cannot be read: %2").arg(path, errorOf()));
    while (q.next()) {
        Vehicle v;
        v.key = q.value(1).toString();
        v.identity.id = v.key.section(QLatin1Char(':'), 1);
        v.identity.name = q.value(2).toString();
        v.identity.protocol = q.value(3).toString();
        v.identity.type = q.value(4).toString();
        v.identity.autopilot = q.value(5).toString();
        vehicleOf.insert(q.value(0).toLongLong(), int(log->m_vehicles.size()));
        log->m_vehicles.push_back(std::move(v));
    }
    if (q.lastError().isValid())
        stop(QObject::tr("the vehicle list is damaged: %1").arg(errorOf()));

    if (q.exec(QStringLiteral("SELECT id, vehicle, t0, data FROM blocks ORDER BY id"))) {
        qint64 good = 0, lastTime = 0, bad = 0;
        while (q.next()) {
            const qint64 vehicleRow = q.value(1).toLongLong();
            const int index = vehicleOf.value(vehicleRow, -1);
            const QByteArray data = q.value(3).toByteArray();
            std::string problem;
            if (index < 0 || !log->m_vehicles[size_t(index)].appendBlock(std::string(data.constData(), size_t(data.size())), &problem)) {
                // One bad block hides nothing else: say which, and go on.
                if (++bad <= kMaxSkippedNamed)
                    log->m_skipped << QObject::tr("block %1 (vehicle row %2, from %3) is skipped: %4")
                                          .arg(q.value(0).toLongLong()).arg(vehicleRow).arg(timeText(q.value(2).toLongLong()),
                                               index < 0 ? QObject::tr("unknown vehicle") : QString::fromStdString(problem));
                continue;
            }
            lastTime = std::max<qint64>(lastTime, log->m_vehicles[size_t(index)].blocks.back().t1);
            ++good;
        }
        if (bad > kMaxSkippedNamed)
            log->m_skipped << QObject::tr("%n more damaged block(s) skipped", nullptr, int(bad - kMaxSkippedNamed));
        if (q.lastError().isValid())
            stop(QObject::tr("stopped after %1 good blocks (%2): %3").arg(good).arg(good ? timeText(lastTime) : QObject::tr("none"), errorOf()));
    } else {
        stop(QObject::tr("the telemetry cannot be read: %1").arg(errorOf()));
    }

    if (q.exec(QStringLiteral("SELECT vehicle, time, kind, text, ok FROM events ORDER BY id"))) {
        while (q.next()) {
            const QVariant ok = q.value(4);
            log->m_events.push_back({q.value(0).isNull() ? -1 : vehicleOf.value(q.value(0).toLongLong(), -1), q.value(1).toLongLong(),
                                     q.value(2).toString(), q.value(3).toString(), ok.isNull() ? -1 : ok.toInt()});
        }
        if (q.lastError().isValid())
            stop(QObject::tr("the events stop after %1: %2").arg(log->m_events.size()).arg(errorOf()));
    } else {
        stop(QObject::tr("the events cannot be read: %1").arg(errorOf()));
    }

    if (q.exec(QStringLiteral("SELECT vehicle, time, items FROM missions ORDER BY id"))) {
        while (q.next()) {
            const int index = vehicleOf.value(q.value(0).toLongLong(), -1);
            bool ok = false;
            auto items = schema::missionFromJson(q.value(2).toString().toUtf8(), &ok);
            if (index >= 0 && ok)
                log->m_vehicles[size_t(index)].missions.push_back({q.value(1).toLongLong(), std::move(items)});
        }
        if (q.lastError().isValid())
            stop(QObject::tr("the routes stop early: %1").arg(errorOf()));
    } else {
        stop(QObject::tr("the routes cannot be read: %1").arg(errorOf()));
    }
    q.finish();
    log->finish();
    if (!log->m_stoppedAt.isEmpty())
        qCWarning(lcFlightLog) << path << "read partly:" << log->m_stoppedAt;
    for (const QString &skipped : std::as_const(log->m_skipped))
        qCWarning(lcFlightLog).noquote() << path << skipped;
    return log;
}

QString FlightLog::damage() const
{
    QStringList parts = m_skipped;
    if (!m_stoppedAt.isEmpty())
        parts << QObject::tr("read up to the last good record: %1").arg(m_stoppedAt);
    return parts.join(QStringLiteral("; "));
}

void FlightLog::addVehicle(Vehicle v)
{
    m_vehicles.push_back(std::move(v));
}

void FlightLog::addEvent(Event e)
{
    m_events.push_back(std::move(e));
}

void FlightLog::finish()
{
    std::stable_sort(m_events.begin(), m_events.end(), [](const Event &a, const Event &b) { return a.time < b.time; });
    bool any = false;
    for (Vehicle &v : m_vehicles) {
        std::stable_sort(v.blocks.begin(), v.blocks.end(), [](const Block &a, const Block &b) { return a.t0 < b.t0; });
        if (v.blocks.empty())
            continue;
        v.start = v.blocks.front().t0;
        v.end = v.blocks.front().t1;
        for (const Block &b : v.blocks) {
            v.start = std::min(v.start, b.t0);
            v.end = std::max(v.end, b.t1);
        }
        m_start = any ? std::min(m_start, v.start) : v.start;
        m_end = any ? std::max(m_end, v.end) : v.end;
        any = true;
    }
    if (any)
        return; // the span is the telemetry's: events without it (a session start) may be on another clock
    for (const Event &e : m_events) { // a log with events only still has a span
        m_start = any ? std::min(m_start, e.time) : e.time;
        m_end = any ? std::max(m_end, e.time) : e.time;
        any = true;
    }
}

int FlightLog::vehicleIndex(const QString &nameOrKey) const
{
    for (size_t i = 0; i < m_vehicles.size(); ++i) {
        if (m_vehicles[i].key == nameOrKey || m_vehicles[i].identity.name == nameOrKey || m_vehicles[i].identity.id == nameOrKey)
            return int(i);
    }
    return -1;
}

std::vector<TelemetrySample> FlightLog::series(int vehicle, TelemetryField field, int64_t from, int64_t to) const
{
    std::vector<TelemetrySample> out;
    if (vehicle < 0 || size_t(vehicle) >= m_vehicles.size())
        return out;
    const Vehicle &v = m_vehicles[size_t(vehicle)];
    out.reserve(size_t(v.counts[size_t(field)]));
    for (const Block &b : v.blocks) {
        if (b.t1 < from || b.t0 > to || !(b.fields & (1u << unsigned(field))))
            continue;
        auto fields = TelemetryBlockCodec::decode(b.data, nullptr, field);
        if (!fields || fields->empty())
            continue;
        for (const TelemetrySample &s : fields->front().samples) {
            if (s.time >= from && s.time <= to)
                out.push_back(s);
        }
    }
    return out;
}

TelemetryBatch FlightLog::updatesBetween(int vehicle, int64_t from, int64_t to) const
{
    TelemetryBatch out;
    if (vehicle < 0 || size_t(vehicle) >= m_vehicles.size() || to <= from)
        return out;
    const Vehicle &v = m_vehicles[size_t(vehicle)];
    // Blocks are in time order; the first one that can hold a sample after `from`.
    auto it = std::partition_point(v.blocks.begin(), v.blocks.end(), [from](const Block &b) { return b.t1 <= from; });
    for (; it != v.blocks.end() && it->t0 <= to; ++it) {
        auto fields = TelemetryBlockCodec::decode(it->data);
        if (!fields)
            continue;
        for (const FieldSamples &f : *fields) {
            for (const TelemetrySample &s : f.samples) {
                if (s.time > from && s.time <= to)
                    out.push_back({f.field, s.value, s.time});
            }
        }
    }
    std::stable_sort(out.begin(), out.end(), [](const auto &a, const auto &b) { return a.time < b.time; });
    return out;
}

std::optional<TelemetryBatch> FlightLog::thinnedSeries(int vehicle, size_t perField, const std::atomic_bool *cancelled) const
{
    if (vehicle < 0 || size_t(vehicle) >= m_vehicles.size())
        return TelemetryBatch{};
    const Vehicle &v = m_vehicles[size_t(vehicle)];
    // Keep every stride-th sample of a field: at most perField of them, spread over the span.
    std::array<uint64_t, vehicle::kTelemetryFieldCount> stride{}, seen{};
    std::array<std::vector<TelemetryUpdate>, vehicle::kTelemetryFieldCount> kept;
    for (size_t f = 0; f < stride.size(); ++f) {
        stride[f] = perField ? std::max<uint64_t>(1, (v.counts[f] + perField - 1) / perField) : 1;
        kept[f].reserve(size_t((v.counts[f] + stride[f] - 1) / stride[f]));
    }
    for (const Block &b : v.blocks) {
        if (cancelled && cancelled->load(std::memory_order_relaxed))
            return std::nullopt;
        const auto fields = TelemetryBlockCodec::decode(b.data);
        if (!fields)
            continue;
        for (const FieldSamples &f : *fields) {
            const size_t i = size_t(f.field);
            for (const TelemetrySample &s : f.samples) {
                if (seen[i]++ % stride[i] == 0)
                    kept[i].push_back({f.field, s.value, s.time});
            }
        }
    }
    TelemetryBatch out;
    size_t total = 0;
    for (const auto &k : kept)
        total += k.size();
    out.reserve(total);
    for (const auto &k : kept)
        out.insert(out.end(), k.begin(), k.end());
    return out;
}

TelemetryBatch FlightLog::stateAt(int vehicle, int64_t time) const
{
    TelemetryBatch out;
    if (vehicle < 0 || size_t(vehicle) >= m_vehicles.size())
        return out;
    const Vehicle &v = m_vehicles[size_t(vehicle)];
    std::array<std::optional<TelemetrySample>, vehicle::kTelemetryFieldCount> last;
    uint32_t wanted = 0;
    for (size_t f = 0; f < vehicle::kTelemetryFieldCount; ++f) {
        if (v.counts[f])
            wanted |= 1u << f;
    }
    // Walk back from the last block that starts by `time`, decoding only blocks that hold a field
    // still missing.
    auto it = std::partition_point(v.blocks.begin(), v.blocks.end(), [time](const Block &b) { return b.t0 <= time; });
    while (wanted && it != v.blocks.begin()) {
        --it;
        if (!(it->fields & wanted))
            continue;
        auto fields = TelemetryBlockCodec::decode(it->data);
        if (!fields)
            continue;
        for (const FieldSamples &f : *fields) {
            const uint32_t bit = 1u << unsigned(f.field);
            if (!(wanted & bit))
                continue;
            for (auto s = f.samples.rbegin(); s != f.samples.rend(); ++s) {
                if (s->time <= time) {
                    last[size_t(f.field)] = *s;
                    wanted &= ~bit;
                    break;
                }
            }
        }
    }
    for (size_t f = 0; f < vehicle::kTelemetryFieldCount; ++f) {
        if (last[f])
            out.push_back({TelemetryField(f), last[f]->value, last[f]->time});
    }
    return out;
}

} // namespace sortie::flightlog
