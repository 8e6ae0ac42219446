#pragma once

#include "FlightLogWriter.h"

#include <QObject>
#include <QPointer>

class QSettings;

namespace sortie::flightlog {

class FlightRecorder;

// The operator's recording limits: read from the settings (flightlog/maxFileMB and
// flightlog/maxFolderMB, 0: no limit) into the recorder when the program starts, changed in the
// flight-log settings dialog (checked here, saved, and applied to the running recorder at once), and
// what the dialog shows beside them: the folder, what it holds, the log being written. The recorder
// owns the limits in force; this object only reads and changes them.
class RecordingSettings : public QObject
{
    Q_OBJECT
    Q_PROPERTY(int maxFileMB READ maxFileMB NOTIFY limitsChanged)
    Q_PROPERTY(int maxFolderMB READ maxFolderMB NOTIFY limitsChanged)
    Q_PROPERTY(QString limitsText READ limitsText NOTIFY limitsChanged)
    Q_PROPERTY(QString folder READ folder CONSTANT)
    Q_PROPERTY(QString folderSummary READ folderSummary NOTIFY folderChanged)
    Q_PROPERTY(QString currentLog READ currentLog NOTIFY currentLogChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY errorChanged)
    Q_PROPERTY(int largestMB READ largestMB CONSTANT)

public:
    static constexpr int kLargestMB = 1 << 20; // 1 TiB: a spin box's range, not a rule

    // Applies the stored limits to the recorder (before it starts, so its first pruning uses them).
    RecordingSettings(QSettings *storage, FlightRecorder *recorder, QObject *parent = nullptr);

    // The limits the settings hold; the defaults (RecordingLimits) for values missing or unreadable.
    static RecordingLimits stored(const QSettings &storage);

    int maxFileMB() const;
    int maxFolderMB() const;
    QString limitsText() const; // the limits in force, in words
    QString folder() const;
    QString folderSummary() const { return m_folderSummary; }
    QString currentLog() const;
    QString errorString() const { return m_error; }
    int largestMB() const { return kLargestMB; }

    // Why these limits cannot be used, or empty.
    static QString check(int maxFileMB, int maxFolderMB);
    // Checks, saves and applies new limits; false (and errorString) when they are refused.
    Q_INVOKABLE bool apply(int maxFileMB, int maxFolderMB);
    // Measures the folder again (the dialog calls it when it opens).
    Q_INVOKABLE void refresh();

signals:
    void limitsChanged();
    void folderChanged();
    void currentLogChanged();
    void errorChanged();

private:
    void setError(const QString &error);

    QSettings *m_storage;
    QPointer<FlightRecorder> m_recorder;
    QString m_folderSummary;
    QString m_error;
};

} // namespace sortie::flightlog
