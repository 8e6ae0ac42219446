#pragma once

#include <QHash>
#include <QObject>
#include <QPointer>

#include <memory>

class QSettings;

namespace sortie::vehicle {
class Vehicle;
}

namespace sortie::video {

class VideoReceiver;
class VideoRuntime;

// Every vehicle's video (docs/video.md, "In the fly view"): the receiver of a vehicle, made when a
// view first asks for it and kept (one per vehicle) until released; its URL is the operator's own
// for that vehicle when one was typed (settings `video/url/<vehicle id>`), else the vehicle's
// `video_stream_uri`, followed as the vehicle changes it. GStreamer is initialised here, explicitly,
// when the first receiver is made (a client that never shows video never starts it).
class VehicleVideo : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool canRecord READ canRecord CONSTANT FINAL)

public:
    // `storage` (not owned) keeps the operator's URLs; null: none kept. `recordingFolder`: where the
    // streams are recorded as received (beside the flight logs); empty: no recording.
    explicit VehicleVideo(QSettings *storage, QString recordingFolder = {}, QObject *parent = nullptr);
    ~VehicleVideo() override;

    // The vehicle's receiver, playing; owned here (null for a null vehicle).
    Q_INVOKABLE sortie::video::VideoReceiver *receiverFor(sortie::vehicle::Vehicle *vehicle);
    // Stops and forgets the vehicle's receiver (the view no longer shows it).
    Q_INVOKABLE void release(sortie::vehicle::Vehicle *vehicle);
    // The operator's URL for the vehicle (empty: the vehicle's own is used).
    Q_INVOKABLE QString manualUrl(sortie::vehicle::Vehicle *vehicle) const;
    Q_INVOKABLE void setManualUrl(sortie::vehicle::Vehicle *vehicle, const QString &url);
    // What the vehicle's receiver plays: the manual URL, else video_stream_uri.
    Q_INVOKABLE QString urlFor(sortie::vehicle::Vehicle *vehicle) const;
    int receivers() const { return int(m_receivers.size()); }
    bool canRecord() const { return !m_recordingFolder.isEmpty(); }
    // Records the vehicle's stream as received (Matroska, no re-encoding) into the recording folder:
    // <vehicle id>-<UTC start>.mkv, its name the clock that lines it up with the flight log.
    Q_INVOKABLE void setRecording(sortie::vehicle::Vehicle *vehicle, bool on);

signals:
    void manualUrlChanged();

private:
    struct Entry
    {
        QPointer<vehicle::Vehicle> vehicle;
        VideoReceiver *receiver = nullptr;
        QMetaObject::Connection uriChanged;
    };
    static QString key(const vehicle::Vehicle *vehicle);

    QSettings *m_storage;
    QString m_recordingFolder;
    std::unique_ptr<VideoRuntime> m_runtime;
    QHash<QString, Entry> m_receivers;  // by vehicle id
};

} // namespace sortie::video
