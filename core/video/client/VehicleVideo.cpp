#include "VehicleVideo.h"

#include "Vehicle.h"
#include "VideoReceiver.h"
#include "VideoRuntime.h"

#include <QSettings>

namespace sortie::video {

VehicleVideo::VehicleVideo(QSettings *storage, QString recordingFolder, QObject *parent)
    : QObject(parent)
    , m_storage(storage)
    , m_recordingFolder(std::move(recordingFolder))
{
}

void VehicleVideo::setRecording(vehicle::Vehicle *vehicle, bool on)
{
    if (VideoReceiver *receiver = vehicle ? receiverFor(vehicle) : nullptr)
        receiver->setRecordingFolder(on ? m_recordingFolder : QString());
}

VehicleVideo::~VehicleVideo()
{
    for (Entry &entry : m_receivers)
        disconnect(entry.uriChanged);
    // Every receiver (released ones waiting for deleteLater too) before the runtime.
    qDeleteAll(findChildren<VideoReceiver *>(Qt::FindDirectChildrenOnly));
}

QString VehicleVideo::key(const vehicle::Vehicle *vehicle)
{
    return QStringLiteral("video/url/%1").arg(vehicle->id());
}

VideoReceiver *VehicleVideo::receiverFor(vehicle::Vehicle *vehicle)
{
    if (!vehicle)
        return nullptr;
    auto it = m_receivers.find(vehicle->id());
    if (it != m_receivers.end())
        return it->receiver;
    if (!m_runtime)
        m_runtime = std::make_unique<VideoRuntime>();
    Entry entry;
    entry.vehicle = vehicle;
    entry.receiver = new VideoReceiver(*m_runtime, this);
    entry.receiver->setObjectName(vehicle->id());
    VideoReceiver *receiver = entry.receiver;
    entry.uriChanged = connect(vehicle, &vehicle::Vehicle::videoStreamUriChanged, receiver, [this, vehicle, receiver] {
        receiver->setUrl(urlFor(vehicle));
    });
    m_receivers.insert(vehicle->id(), entry);
    receiver->setUrl(urlFor(vehicle));
    return receiver;
}

void VehicleVideo::release(vehicle::Vehicle *vehicle)
{
    if (!vehicle)
        return;
    auto it = m_receivers.find(vehicle->id());
    if (it == m_receivers.end())
        return;
    disconnect(it->uriChanged);
    it->receiver->stop();
    it->receiver->deleteLater();  // a view may still hold it for this turn of the loop
    m_receivers.erase(it);
}

QString VehicleVideo::manualUrl(vehicle::Vehicle *vehicle) const
{
    return vehicle && m_storage ? m_storage->value(key(vehicle)).toString() : QString();
}

void VehicleVideo::setManualUrl(vehicle::Vehicle *vehicle, const QString &url)
{
    if (!vehicle || !m_storage || manualUrl(vehicle) == url.trimmed())
        return;
    if (url.trimmed().isEmpty())
        m_storage->remove(key(vehicle));
    else
        m_storage->setValue(key(vehicle), url.trimmed());
    if (auto it = m_receivers.find(vehicle->id()); it != m_receivers.end())
        it->receiver->setUrl(urlFor(vehicle));
    emit manualUrlChanged();
}

QString VehicleVideo::urlFor(vehicle::Vehicle *vehicle) const
{
    if (!vehicle)
        return {};
    const QString manual = manualUrl(vehicle);
    return manual.isEmpty() ? vehicle->videoStreamUri() : manual;
}

} // namespace sortie::video
