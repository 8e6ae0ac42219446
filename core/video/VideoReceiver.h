#pragma once

#include "VideoSource.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QImage>
#include <QMutex>
#include <QObject>
#include <QSize>
#include <QTimer>

#include <atomic>
#include <memory>

namespace sortie::video {

class VideoRuntime;

// One decoded picture as the receiver hands it over: the image (BGRx as QImage::Format_RGB32,
// sharing the decoder's buffer, no copy), when the pipeline delivered it (FrameStamp::nowMicros)
// and its number since the receiver started.
struct VideoFrame
{
    QImage image;
    qint64 receivedUs = 0;
    quint64 number = 0;
};

// Receives one stream (docs/video.md): a GStreamer pipeline from the source (rtspsrc, or udpsrc and
// rtpjitterbuffer, or udpsrc and tsdemux) through decodebin (hardware decoders where the system
// has them, libav otherwise) and videoconvert to an appsink that keeps one buffer, drops the rest
// and does not wait for the clock. The streaming thread hands each frame over under a mutex and
// posts one notification at a time to this object's thread (frameReady); the picture drawn is the
// latest one, the ones it replaced before anyone looked are counted as dropped.
//
// GStreamer's bus is polled on a QTimer in this object's thread (no GLib main loop). States:
// Idle (no URL or stopped), Connecting (no frame yet), Playing, Stalled (no frame for stallMs: the
// pipeline is rebuilt every reconnectMs until frames come again) and Error (a bad URL or a missing
// plugin: nothing to retry until the URL changes; missingPackage names what to install).
class VideoReceiver : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QString url READ url NOTIFY sourceChanged FINAL)
    Q_PROPERTY(QString sourceDescription READ sourceDescription NOTIFY sourceChanged FINAL)
    Q_PROPERTY(sortie::video::VideoReceiver::State state READ state NOTIFY stateChanged FINAL)
    Q_PROPERTY(QString errorString READ errorString NOTIFY stateChanged FINAL)
    Q_PROPERTY(QString lastProblem READ lastProblem NOTIFY stateChanged FINAL)
    Q_PROPERTY(QString missingPackage READ missingPackage NOTIFY stateChanged FINAL)
    Q_PROPERTY(QDateTime lastFrameTime READ lastFrameTime NOTIFY stateChanged FINAL)
    Q_PROPERTY(QString decoderName READ decoderName NOTIFY decoderChanged FINAL)
    Q_PROPERTY(bool hardwareDecoding READ hardwareDecoding NOTIFY decoderChanged FINAL)
    Q_PROPERTY(QSize frameSize READ frameSize NOTIFY decoderChanged FINAL)
    Q_PROPERTY(bool recording READ isRecording NOTIFY recordingChanged FINAL)
    Q_PROPERTY(QString recordingFile READ recordingFile NOTIFY recordingChanged FINAL)

public:
    enum class State { Idle, Connecting, Playing, Stalled, Error };
    Q_ENUM(State)

    struct Options
    {
        int stallMs = 2000;        // no frame for this long while playing: stalled
        int reconnectMs = 1500;    // a new attempt this often while stalled or connecting
        int rtspAttemptMs = 6000;  // an RTSP attempt's time to its first frame (UDP, then TCP after 2 s)
        int busPollMs = 20;
    };

    explicit VideoReceiver(VideoRuntime &runtime, QObject *parent = nullptr);
    VideoReceiver(VideoRuntime &runtime, Options options, QObject *parent = nullptr);
    ~VideoReceiver() override;

    // Parses the URL and plays it (an empty URL stops: Idle). A bad URL: Error with its reason.
    void setUrl(const QString &url);
    void setSource(const VideoSource &source);
    void stop();
    // Records the stream as received (no re-encoding) into this folder, a Matroska file per pipeline
    // built: <objectName>-<UTC start>.mkv. Empty: no recording. Starting or stopping rebuilds the
    // pipeline (the picture resumes at the next key frame).
    void setRecordingFolder(const QString &folder);
    bool isRecording() const { return !m_recordingFolder.isEmpty(); }
    QString recordingFile() const { return m_recordingFile; }

    QString url() const { return m_url; }
    QString sourceDescription() const;
    State state() const { return m_state; }
    QString errorString() const { return m_error; }
    // The last thing that went wrong with a stream that is retried (refused, a decoding error...).
    QString lastProblem() const { return m_lastProblem; }
    QString missingPackage() const { return m_missingPackage; }
    QDateTime lastFrameTime() const { return m_lastFrameTime; }
    QString decoderName() const { return m_decoderName; }
    bool hardwareDecoding() const { return m_hardware; }
    QSize frameSize() const { return m_frameSize; }

    // The latest frame (thread-safe; a null image before the first one).
    VideoFrame latestFrame() const;
    quint64 framesReceived() const { return m_received.load(); }
    // Frames replaced before anyone took them (the view drew slower than the stream came).
    quint64 framesDropped() const { return m_dropped.load(); }
    int attempts() const { return m_attempts; }
    // RTP packets dropped before the depayloader as cut short or malformed (RtpSanity.h).
    quint64 packetsRefused() const { return m_refused.load(); }

    // "Connecting…", "No video since 14:02:07 (00:07)", "Install gstreamer1.0-libav: …".
    Q_INVOKABLE QString statusText() const;

signals:
    void frameReady();
    void stateChanged();
    void sourceChanged();
    void decoderChanged();
    void recordingChanged();

private:
    struct Pipeline;
    friend struct Pipeline;

    void build();
    void teardown();
    void pollBus();
    void watch();

    void setState(State state);
    void fail(const QString &error, const QString &package = {});
    void retryLater(const QString &problem);
    void findDecoder();
    // Called on the streaming thread.
    void handOver(QImage image, qint64 receivedUs, quint64 generation);
    void onFrameArrived(quint64 generation);

    VideoRuntime &m_runtime;
    Options m_options;
    QString m_url;
    std::optional<VideoSource> m_source;
    std::unique_ptr<Pipeline> m_pipeline;
    QTimer m_busTimer;
    QTimer m_watchdog;
    QElapsedTimer m_attemptClock;   // since the pipeline was built
    QElapsedTimer m_frameClock;     // since the last frame
    bool m_frameThisAttempt = false;
    int m_attempts = 0;
    std::atomic<quint64> m_generation{0};  // one per pipeline: a late notification of an old one is ignored

    State m_state = State::Idle;
    QString m_error;
    QString m_lastProblem;
    QString m_missingPackage;
    QDateTime m_lastFrameTime;
    QString m_decoderName;
    bool m_hardware = false;
    QSize m_frameSize;
    QString m_recordingFolder;
    QString m_recordingFile;

    mutable QMutex m_frameMutex;
    VideoFrame m_frame;          // guarded by m_frameMutex
    mutable bool m_frameTaken = true;    // guarded by m_frameMutex
    std::atomic<bool> m_notifyPending{false};
    std::atomic<quint64> m_received{0};
    std::atomic<quint64> m_dropped{0};
    std::atomic<quint64> m_refused{0};
};

} // namespace sortie::video
