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

public:
    // `storage` (not owned) keeps the operator's URLs; null: none kept.
    explicit VehicleVideo(QSettings *storage, QObject *parent = nullptr);
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
    std::unique_ptr<VideoRuntime> m_runtime;
    QHash<QString, Entry> m_receivers;  // by vehicle id
};

} // namespace sortie::video
