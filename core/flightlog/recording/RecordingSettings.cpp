#include "RecordingSettings.h"

#include "FlightLogLog.h"
#include "FlightRecorder.h"

#include <QDir>
#include <QFileInfo>
#include <QLocale>
#include <QSettings>

namespace sortie::flightlog {

namespace {

const QString kMaxFileKey = QStringLiteral("flightlog/maxFileMB");
const QString kMaxFolderKey = QStringLiteral("flightlog/maxFolderMB");

qint64 storedMB(const QSettings &storage, const QString &key, qint64 fallbackBytes)
{
    bool ok = false;
    const qint64 mb = storage.value(key).toLongLong(&ok);
    if (!storage.contains(key))
        return fallbackBytes;
    if (!ok || mb < 0 || mb > RecordingSettings::kLargestMB) {
        qCWarning(lcFlightLog) << "setting" << key << "is no size in MB:" << storage.value(key).toString() << "- using the default";
        return fallbackBytes;
    }
    return mb << 20;
}

} // namespace

RecordingSettings::RecordingSettings(QSettings *storage, FlightRecorder *recorder, QObject *parent)
    : QObject(parent)
    , m_storage(storage)
    , m_recorder(recorder)
{
    if (m_recorder) {
        m_recorder->setLimits(stored(*m_storage));
        connect(m_recorder, &FlightRecorder::limitsChanged, this, &RecordingSettings::limitsChanged);
        connect(m_recorder, &FlightRecorder::pathChanged, this, [this] {
            emit currentLogChanged();
            refresh(); // a rotation may have pruned
        });
    }
    refresh();
}

RecordingLimits RecordingSettings::stored(const QSettings &storage)
{
    const RecordingLimits defaults;
    return {storedMB(storage, kMaxFileKey, defaults.maxFileBytes), storedMB(storage, kMaxFolderKey, defaults.maxFolderBytes)};
}

int RecordingSettings::maxFileMB() const
{
    return m_recorder ? int(m_recorder->limits().maxFileBytes >> 20) : 0;
}

int RecordingSettings::maxFolderMB() const
{
    return m_recorder ? int(m_recorder->limits().maxFolderBytes >> 20) : 0;
}

QString RecordingSettings::limitsText() const
{
    const int file = maxFileMB(), folder = maxFolderMB();
    return tr("In force: %1; %2.")
        .arg(file > 0 ? tr("a log up to %1 MB").arg(file) : tr("logs of any size"),
             folder > 0 ? tr("the folder up to %1 MB").arg(folder) : tr("the folder without limit"));
}

QString RecordingSettings::folder() const
{
    return m_recorder ? QDir::toNativeSeparators(m_recorder->folder()) : QString();
}

QString RecordingSettings::currentLog() const
{
    return m_recorder && m_recorder->isRecording() ? QFileInfo(m_recorder->path()).fileName() : QString();
}

QString RecordingSettings::check(int maxFileMB, int maxFolderMB)
{
    if (maxFileMB < 0 || maxFileMB > kLargestMB)
        return tr("A log's size must be between 1 and %1 MB, or 0 for no limit.").arg(kLargestMB);
    if (maxFolderMB < 0 || maxFolderMB > kLargestMB)
        return tr("The folder's size must be between 1 and %1 MB, or 0 for no limit.").arg(kLargestMB);
    if (maxFolderMB > 0 && maxFileMB > maxFolderMB)
        return tr("The folder must hold at least one whole log: make its limit at least a log's size (%1 MB).").arg(maxFileMB);
    return {};
}

bool RecordingSettings::apply(int maxFileMB, int maxFolderMB)
{
    const QString problem = check(maxFileMB, maxFolderMB);
    setError(problem);
    if (!problem.isEmpty())
        return false;
    m_storage->setValue(kMaxFileKey, maxFileMB);
    m_storage->setValue(kMaxFolderKey, maxFolderMB);
    if (m_recorder)
        m_recorder->setLimits({qint64(maxFileMB) << 20, qint64(maxFolderMB) << 20});
    return true;
}

void RecordingSettings::refresh()
{
    int logs = 0;
    const qint64 bytes = m_recorder ? FlightLogWriter::folderBytes(m_recorder->folder(), &logs) : 0;
    const QString summary = logs == 1 ? tr("%1 in 1 log").arg(QLocale().formattedDataSize(bytes, 2, QLocale::DataSizeTraditionalFormat))
                                      : tr("%1 in %2 logs").arg(QLocale().formattedDataSize(bytes, 2, QLocale::DataSizeTraditionalFormat)).arg(logs);
    if (summary == m_folderSummary)
        return;
    m_folderSummary = summary;
    emit folderChanged();
}

void RecordingSettings::setError(const QString &error)
{
    if (error == m_error)
        return;
    m_error = error;
    emit errorChanged();
}

} // namespace sortie::flightlog
