#include "AutosaveWriter.h"

#include "AtomicFile.h"

#include <QCoreApplication>
#include <QFile>

namespace sortie::client {

AutosaveWriter::AutosaveWriter(QString path)
    : m_path(std::move(path))
    , m_baseline(encodeAutosaveRoute(mission::Route{}))
{
}

bool AutosaveWriter::queueWrite(AutosaveRecord header, mission::Route working, std::optional<mission::Route> baseline)
{
    Job job;
    job.kind = Job::Write;
    job.header = std::move(header);
    job.header.working = std::move(working);
    job.baseline = std::move(baseline);
    const std::lock_guard lock(m_mutex);
    const bool wasEmpty = m_jobs.empty();
    if (!wasEmpty && m_jobs.back().kind == Job::Write) {
        if (!job.baseline) // the newest snapshot wins, with the newest baseline
            job.baseline = std::move(m_jobs.back().baseline);
        m_jobs.back() = std::move(job);
    } else
        m_jobs.push_back(std::move(job));
    return wasEmpty;
}

bool AutosaveWriter::queueRemove(std::optional<mission::Route> baseline)
{
    Job job;
    job.kind = Job::Remove;
    job.baseline = std::move(baseline);
    const std::lock_guard lock(m_mutex);
    const bool wasEmpty = m_jobs.empty();
    // Writes still waiting would only be removed again; an earlier new baseline is replaced by
    // this one unless this removal brings none.
    std::optional<mission::Route> earlierBaseline;
    for (Job &waiting : m_jobs) {
        if (waiting.baseline)
            earlierBaseline = std::move(waiting.baseline);
    }
    if (!job.baseline)
        job.baseline = std::move(earlierBaseline);
    m_jobs.clear();
    m_jobs.push_back(std::move(job));
    return wasEmpty;
}

int AutosaveWriter::queued() const
{
    const std::lock_guard lock(m_mutex);
    return int(m_jobs.size());
}

QString AutosaveWriter::drain()
{
    for (;;) {
        Job job;
        {
            const std::lock_guard lock(m_mutex);
            if (m_jobs.empty())
                return m_lastError;
            job = std::move(m_jobs.front());
            m_jobs.pop_front();
        }
        m_lastError = run(job);
    }
}

QString AutosaveWriter::run(Job &job)
{
    if (job.kind == Job::Remove) {
        if (job.baseline)
            m_baseline = encodeAutosaveRoute(*job.baseline);
        if (!QFile::exists(m_path))
            return {};
        QFile file(m_path);
        if (!file.remove()) {
            const QString error = QCoreApplication::translate("AutosaveWriter", "Cannot remove %1: %2").arg(m_path, file.errorString());
            emit failed(error);
            return error;
        }
        emit removed();
        return {};
    }
    if (job.baseline)
        m_baseline = encodeAutosaveRoute(*job.baseline);
    const QByteArray data = encodeAutosave(job.header, encodeAutosaveRoute(job.header.working), m_baseline);
    const QString error = writeFileAtomically(m_path, data);
    if (!error.isEmpty()) {
        emit failed(error);
        return error;
    }
    emit written(m_path);
    return {};
}

} // namespace sortie::client
