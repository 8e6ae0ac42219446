#pragma once

#include "SbsReader.h"

#include <QObject>
#include <QTcpSocket>
#include <QTimer>

namespace sortie::traffic {

class TrafficPicture;

// An ADS-B receiver's SBS-1 feed (dump1090, readsb: TCP port 30003) into the picture. Connects to
// host:port, reads lines as they come (SbsReader: a bad line is dropped, counted and named in
// lastDropped, never believed) and reconnects after a failure or a hang-up with a back-off: 1 s,
// doubling up to 30 s, back to 1 s once connected. A connection attempt gives up after 10 s. An
// empty address turns the feed off.
class SbsFeed : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QString address READ address NOTIFY addressChanged)
    Q_PROPERTY(State state READ state NOTIFY stateChanged)
    Q_PROPERTY(QString error READ error NOTIFY stateChanged)     // why the last connection failed or ended
    Q_PROPERTY(QString statusText READ statusText NOTIFY stateChanged)
    Q_PROPERTY(int messages READ messages NOTIFY countsChanged)
    Q_PROPERTY(int droppedLines READ droppedLines NOTIFY countsChanged)
    Q_PROPERTY(QString lastDropped READ lastDropped NOTIFY countsChanged) // "line 12: field 15 (latitude): ..."

public:
    enum class State { Off, Connecting, Connected, Waiting };
    Q_ENUM(State)
    static constexpr int kFirstRetryMs = 1000;
    static constexpr int kMaxRetryMs = 30000;
    static constexpr int kConnectTimeoutMs = 10000;
    // Per turn of the event loop at most kBytesPerTurn are taken from the socket (about 700 lines:
    // well under a frame of work); the rest waits in a socket buffer of kBufferBytes, and past that
    // in the kernel's, so a flood slows the sender instead of filling memory or the GUI thread.
    static constexpr qint64 kBytesPerTurn = 64 * 1024;
    static constexpr qint64 kBufferBytes = 1024 * 1024;

    explicit SbsFeed(TrafficPicture *picture, QObject *parent = nullptr);
    ~SbsFeed() override;

    // "host:port" (an IPv6 host in brackets); empty: off. False, with error() saying why, when the
    // address cannot be one; the feed is then off.
    bool setAddress(const QString &address);
    QString address() const { return m_address; }
    State state() const { return m_state; }
    QString error() const { return m_error; }
    QString statusText() const;
    int messages() const { return m_messages; }
    int droppedLines() const { return m_dropped; }
    QString lastDropped() const { return m_lastDropped; }
    int retryDelayMs() const { return m_retryMs; }

    // Splits "host:port"; false when it is not one.
    static bool parseAddress(const QString &address, QString *host, quint16 *port);

signals:
    void addressChanged();
    void stateChanged();
    void countsChanged();

private:
    void connectNow();
    void onConnected();
    void onReadyRead();
    void readSome();
    void onFailure(const QString &why);
    void setState(State state);

    TrafficPicture *m_picture;
    QTcpSocket m_socket;
    QTimer m_retry;
    QTimer m_connectTimeout;
    sbs::SbsReader m_reader;
    QString m_address;
    QString m_host;
    quint16 m_port = 0;
    State m_state = State::Off;
    QString m_error;
    int m_retryMs = kFirstRetryMs;
    int m_messages = 0;
    int m_dropped = 0;
    QString m_lastDropped;
    bool m_turnQueued = false;
};

} // namespace sortie::traffic
