#include "FlightLogWriter.h"

#include "FlightLogLog.h"
#include "FlightLogSchema.h"
#include "PrivateFiles.h"

#include <QDir>
#include <QFileInfo>
#include <QLockFile>
#include <QSqlError>
#include <QSqlQuery>
#include <QUuid>

#include <time.h>

namespace sortie::flightlog {

namespace {

// QtSql binds a null QString as SQL NULL; a vehicle that does not report its type has an empty one.
QString notNull(const QString &text)
{
    return text.isNull() ? QStringLiteral("") : text;
}
qint64 threadCpuNs()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return qint64(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// The lock a writer holds on the log it writes: what another process's pruning asks first.
QString lockPath(const QString &log)
{
    return log + QStringLiteral(".lock");
}

std::unique_ptr<QLockFile> lockLog(const QString &log)
{
    auto lock = std::make_unique<QLockFile>(lockPath(log));
    lock->setStaleLockTime(0); // only a dead holder makes it stale, however long a flight lasts
    return lock->tryLock(0) ? std::move(lock) : nullptr;
}

QString partPath(const QString &base, int part)
{
    if (part <= 1)
        return base;
    const QFileInfo info(base);
    return info.dir().filePath(QStringLiteral("%1-%2%3").arg(info.completeBaseName()).arg(part).arg(QLatin1String(schema::kSuffix)));
}
quint64 valueCount(const RecordingChunk &chunk)
{
    quint64 count = 0;
    for (const RecordedSamples &s : chunk.samples)
        for (const FieldSamples &f : s.fields)
            count += f.samples.size();
    return count;
}
} // namespace

FlightLogWriter::FlightLogWriter(QString path, RecordingLimits limits, QObject *parent)
    : QObject(parent)
    , m_basePath(std::move(path))
    , m_connection(QStringLiteral("flightlog-writer-") + QUuid::createUuid().toString(QUuid::WithoutBraces))
    , m_maxFileBytes(limits.maxFileBytes)
    , m_maxFolderBytes(limits.maxFolderBytes)
{
}

FlightLogWriter::~FlightLogWriter()
{
    close();
}

bool FlightLogWriter::open(QString *error)
{
    if (!files::makePrivatePath(QFileInfo(m_basePath).absolutePath(), error))
        return false;
    m_parts = 0;
    return openPart(m_basePath, error);
}

bool FlightLogWriter::openPart(const QString &path, QString *error)
{
    m_lock = lockLog(path);
    if (!m_lock) {
        if (error)
            *error = tr("%1 is being written by another process").arg(path);
        return false;
    }
    // 0600 before SQLite opens it: the journals it makes beside it take the file's mode.
    if (!files::createPrivateFile(path, error)) {
        m_lock.reset();
        return false;
    }
    m_db = schema::open(path, m_connection, false, error);
    if (!m_db.isOpen()) {
        m_lock.reset();
        return false;
    }
    QSqlQuery q(m_db);
    // WAL: a commit appends to the log file, readers (a replay of the running session) never block
    // the writer, and a torn last transaction is ignored on the next open. FULL syncs the WAL at each
    // commit (once per flush): a power cut loses at most the flush in flight.
    q.exec(QStringLiteral("PRAGMA journal_mode=WAL"));
    q.next();
    if (q.value(0).toString().compare(QLatin1String("wal"), Qt::CaseInsensitive) != 0) {
        if (error)
            *error = tr("%1: the log cannot use a write-ahead journal").arg(path);
        m_db.close();
        m_lock.reset();
        return false;
    }
    q.exec(QStringLiteral("PRAGMA synchronous=FULL"));
    if (!schema::create(m_db, error)) {
        m_db.close();
        m_lock.reset();
        return false;
    }
    {
        QMutexLocker lock(&m_pathMutex);
        m_path = path;
    }
    m_vehicleRows.clear();
    ++m_parts;
    m_failed = false;
    qCInfo(lcFlightLog) << "recording to" << path;
    return true;
}

void FlightLogWriter::close()
{
    if (!m_db.isValid())
        return;
    if (m_db.isOpen() && !m_unwritten.empty()) { // a last try: the disk may have room again
        QString error;
        while (!m_unwritten.empty() && commit(m_unwritten.front(), &error))
            m_unwritten.pop_front();
        if (!m_unwritten.empty())
            qCWarning(lcFlightLog).noquote() << m_unwritten.size() << "recorded chunks could not be written to" << currentPath() << ":" << error;
        m_unwritten.clear();
        m_unwrittenValues = 0;
    }
    if (m_db.isOpen()) {
        QSqlQuery q(m_db);
        q.exec(QStringLiteral("PRAGMA wal_checkpoint(TRUNCATE)")); // a closed log is one file again
        q.finish();
        m_db.close();
    }
    m_db = QSqlDatabase();
    QSqlDatabase::removeDatabase(m_connection);
    m_lock.reset(); // after the file is closed: a pruning process may delete it from now on
}

QString FlightLogWriter::currentPath() const
{
    QMutexLocker lock(&m_pathMutex);
    return m_path;
}

FlightLogWriter::Stats FlightLogWriter::stats() const
{
    return {m_values.load(), m_blocks.load(), m_blockBytes.load(), m_cpuNs.load(), m_parts.load()};
}

void FlightLogWriter::write(const RecordingChunk &chunk)
{
    if (!m_db.isOpen() || chunk.empty())
        return;
    const qint64 start = threadCpuNs();
    QString error;
    // What failed before goes first, in order, so the log's blocks stay in time order.
    bool ok = true;
    while (ok && !m_unwritten.empty()) {
        ok = commit(m_unwritten.front(), &error);
        if (ok) {
            m_unwrittenValues -= std::min(m_unwrittenValues, valueCount(m_unwritten.front()));
            m_unwritten.pop_front();
        }
    }
    ok = ok && commit(chunk, &error);
    if (!ok) {
        keepUnwritten(chunk);
        if (!m_failed) { // say it once, not every second
            m_failed = true;
            qCWarning(lcFlightLog) << "recording failed:" << error;
            emit errorOccurred(tr("Recording to %1 failed: %2. What is recorded meanwhile is kept and written once it can be.")
                                   .arg(currentPath(), error));
        }
    } else {
        if (m_failed) {
            qCInfo(lcFlightLog) << "recording resumed: the chunks that had failed are written";
            emit errorOccurred(m_droppedValues ? tr("Recording to %1 resumed; %n value(s) recorded while it failed could not be kept.", nullptr,
                                                    int(std::min<quint64>(m_droppedValues, INT_MAX))).arg(currentPath())
                                               : QString());
        }
        m_failed = false;
        m_droppedValues = 0;
        const qint64 maxFile = m_maxFileBytes.load();
        if (maxFile > 0 && sizeOnDisk() > maxFile)
            rotate();
    }
    m_cpuNs += threadCpuNs() - start;
}

bool FlightLogWriter::commit(const RecordingChunk &chunk, QString *error)
{
    if (writeChunk(chunk, error))
        return true;
    m_db.rollback();
    // The rollback took back the vehicle rows this transaction inserted: look them up (and insert
    // them) again rather than name rows that do not exist.
    m_vehicleRows.clear();
    return false;
}

void FlightLogWriter::keepUnwritten(const RecordingChunk &chunk)
{
    m_unwritten.push_back(chunk);
    m_unwrittenValues += valueCount(chunk);
    // Bounded: beyond the limit the oldest telemetry goes (its vehicles, events and routes stay).
    for (RecordingChunk &oldest : m_unwritten) {
        if (m_unwrittenValues <= kMaxUnwrittenValues)
            break;
        const quint64 values = valueCount(oldest);
        oldest.samples.clear();
        m_unwrittenValues -= std::min(m_unwrittenValues, values);
        m_droppedValues += values;
    }
}

qint64 FlightLogWriter::vehicleRow(const QString &key)
{
    const auto it = m_vehicleRows.constFind(key);
    if (it != m_vehicleRows.constEnd())
        return *it;
    // A vehicle whose identity never came: a row under its key, so its telemetry has somewhere to go.
    RecordedVehicle v{key, {}};
    v.identity.id = key;
    QSqlQuery q(m_db);
    q.prepare(QStringLiteral("INSERT INTO vehicles(key, name, protocol, type, autopilot) VALUES (?, ?, '', '', '')"
                             " ON CONFLICT(key) DO NOTHING"));
    q.addBindValue(key);
    q.addBindValue(key);
    q.exec();
    q.prepare(QStringLiteral("SELECT id FROM vehicles WHERE key = ?"));
    q.addBindValue(key);
    if (!q.exec() || !q.next())
        return -1;
    const qint64 row = q.value(0).toLongLong();
    m_vehicleRows.insert(key, row);
    return row;
}

bool FlightLogWriter::writeChunk(const RecordingChunk &chunk, QString *error)
{
    auto failed = [error](const QSqlQuery &q) {
        *error = q.lastError().text();
        return false;
    };
    if (!m_db.transaction()) {
        *error = m_db.lastError().text();
        return false;
    }
    QSqlQuery q(m_db);
    const auto rowOf = [this, error](const QString &key, qint64 *row) {
        *row = vehicleRow(key);
        if (*row < 0)
            *error = tr("no row for vehicle %1: %2").arg(key, m_db.lastError().text());
        return *row >= 0;
    };
    quint64 values = 0, blocks = 0, blockBytes = 0; // counted once committed
    for (const RecordedVehicle &v : chunk.vehicles) {
        m_vehicles.insert(v.key, v);
        q.prepare(QStringLiteral("INSERT INTO vehicles(key, name, protocol, type, autopilot) VALUES (?, ?, ?, ?, ?)"
                                 " ON CONFLICT(key) DO UPDATE SET name = excluded.name, protocol = excluded.protocol,"
                                 " type = excluded.type, autopilot = excluded.autopilot"));
        q.addBindValue(v.key);
        q.addBindValue(notNull(v.identity.name.isEmpty() ? v.identity.id : v.identity.name));
        q.addBindValue(notNull(v.identity.protocol));
        q.addBindValue(notNull(v.identity.type));
        q.addBindValue(notNull(v.identity.autopilot));
        if (!q.exec())
            return failed(q);
    }
    if (!chunk.samples.empty()) {
        q.prepare(QStringLiteral("INSERT INTO blocks(vehicle, t0, t1, count, data) VALUES (?, ?, ?, ?, ?)"));
        for (const RecordedSamples &s : chunk.samples) {
            int64_t t0 = INT64_MAX, t1 = INT64_MIN;
            size_t count = 0;
            for (const FieldSamples &f : s.fields) {
                if (f.samples.empty())
                    continue;
                for (const auto &sample : f.samples) {
                    t0 = std::min(t0, sample.time);
                    t1 = std::max(t1, sample.time);
                }
                count += f.samples.size();
            }
            if (!count)
                continue;
            const std::string block = TelemetryBlockCodec::encode(s.fields);
            qint64 row = -1;
            if (!rowOf(s.vehicleKey, &row))
                return false;
            q.addBindValue(row);
            q.addBindValue(qint64(t0));
            q.addBindValue(qint64(t1));
            q.addBindValue(qint64(count));
            q.addBindValue(QByteArray::fromRawData(block.data(), qsizetype(block.size())));
            if (!q.exec())
                return failed(q);
            values += count;
            ++blocks;
            blockBytes += block.size();
        }
    }
    if (!chunk.events.empty()) {
        q.prepare(QStringLiteral("INSERT INTO events(vehicle, time, kind, text, ok) VALUES (?, ?, ?, ?, ?)"));
        for (const RecordedEvent &e : chunk.events) {
            qint64 row = -1;
            if (!e.vehicleKey.isEmpty() && !rowOf(e.vehicleKey, &row))
                return false;
            q.addBindValue(e.vehicleKey.isEmpty() ? QVariant() : QVariant(row));
            q.addBindValue(qint64(e.time));
            q.addBindValue(notNull(e.kind));
            q.addBindValue(notNull(e.text));
            q.addBindValue(e.ok < 0 ? QVariant() : QVariant(e.ok));
            if (!q.exec())
                return failed(q);
        }
    }
    if (!chunk.missions.empty()) {
        q.prepare(QStringLiteral("INSERT INTO missions(vehicle, time, items) VALUES (?, ?, ?)"));
        for (const RecordedMission &m : chunk.missions) {
            m_lastMissions.insert(m.vehicleKey, m);
            qint64 row = -1;
            if (!rowOf(m.vehicleKey, &row))
                return false;
            q.addBindValue(row);
            q.addBindValue(qint64(m.time));
            q.addBindValue(QString::fromUtf8(schema::missionToJson(m.items)));
            if (!q.exec())
                return failed(q);
        }
    }
    if (!m_db.commit()) {
        *error = m_db.lastError().text();
        return false;
    }
    m_values += values;
    m_blocks += blocks;
    m_blockBytes += blockBytes;
    return true;
}

qint64 FlightLogWriter::sizeOnDisk()
{
    QSqlQuery q(m_db);
    if (!q.exec(QStringLiteral("PRAGMA page_count")) || !q.next())
        return 0;
    const qint64 pages = q.value(0).toLongLong();
    if (!q.exec(QStringLiteral("PRAGMA page_size")) || !q.next())
        return 0;
    return pages * q.value(0).toLongLong();
}

void FlightLogWriter::rotate()
{
    close();
    const QString next = partPath(m_basePath, m_parts + 1);
    QString error;
    if (!openPart(next, &error)) {
        m_failed = true;
        emit errorOccurred(tr("Recording could not continue in %1: %2").arg(next, error));
        return;
    }
    // Each part stands on its own: it names its vehicles and holds their routes again.
    RecordingChunk carry;
    for (const RecordedVehicle &v : std::as_const(m_vehicles))
        carry.vehicles.push_back(v);
    for (const RecordedMission &m : std::as_const(m_lastMissions))
        carry.missions.push_back(m);
    if (!commit(carry, &error))
        keepUnwritten(carry);
    if (m_maxFolderBytes.load() > 0)
        pruneFolder(QFileInfo(next).absolutePath(), m_maxFolderBytes.load(), next);
    emit rotated(next);
}

void FlightLogWriter::setLimits(RecordingLimits limits)
{
    m_maxFileBytes = limits.maxFileBytes;
    m_maxFolderBytes = limits.maxFolderBytes;
    qCInfo(lcFlightLog) << "recording limits now" << (limits.maxFileBytes >> 20) << "MB a log," << (limits.maxFolderBytes >> 20) << "MB the folder";
}

void FlightLogWriter::enforceLimits()
{
    if (!m_db.isOpen())
        return;
    const qint64 maxFile = m_maxFileBytes.load();
    if (maxFile > 0 && sizeOnDisk() > maxFile) {
        rotate(); // prunes too
        return;
    }
    if (m_maxFolderBytes.load() > 0) {
        const QString path = currentPath();
        pruneFolder(QFileInfo(path).absolutePath(), m_maxFolderBytes.load(), path);
    }
}

namespace {

QFileInfoList logsIn(const QDir &dir)
{
    return dir.entryInfoList({QStringLiteral("*") + QLatin1String(schema::kSuffix)}, QDir::Files, QDir::Time | QDir::Reversed);
}

qint64 sizeWithJournal(const QFileInfo &log)
{
    return log.size() + QFileInfo(log.absoluteFilePath() + QStringLiteral("-wal")).size();
}

} // namespace

qint64 FlightLogWriter::folderBytes(const QString &folder, int *logs)
{
    const QFileInfoList files = logsIn(QDir(folder));
    qint64 total = 0;
    for (const QFileInfo &f : files)
        total += sizeWithJournal(f);
    if (logs)
        *logs = int(files.size());
    return total;
}

QStringList FlightLogWriter::pruneFolder(const QString &folder, qint64 maxBytes, const QString &keep)
{
    const QFileInfoList logs = logsIn(QDir(folder));
    qint64 total = 0;
    for (const QFileInfo &f : logs)
        total += sizeWithJournal(f);
    QStringList removed;
    const QString kept = QFileInfo(keep).absoluteFilePath();
    for (const QFileInfo &f : logs) { // oldest first
        if (total <= maxBytes)
            break;
        if (f.absoluteFilePath() == kept)
            continue;
        // A log some writer holds the lock of (this process's, another client's, a `sortie-log
        // record`) is being written: never deleted. Held while deleting, so none starts meanwhile.
        const auto lock = lockLog(f.absoluteFilePath());
        if (!lock) {
            qCInfo(lcFlightLog) << "kept" << f.fileName() << "(being written by another recording)";
            continue;
        }
        total -= sizeWithJournal(f);
        QFile::remove(f.absoluteFilePath());
        QFile::remove(f.absoluteFilePath() + QStringLiteral("-wal"));
        QFile::remove(f.absoluteFilePath() + QStringLiteral("-shm"));
        removed.append(f.absoluteFilePath());
        qCInfo(lcFlightLog) << "removed old log" << f.fileName() << "(folder over its limit)";
    }
    return removed;
}

} // namespace sortie::flightlog
