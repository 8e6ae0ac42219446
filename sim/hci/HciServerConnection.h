#pragma once

#include "HciFrameCodec.h"
#include "SimFaults.h"

#include <QObject>
#include <QTimer>

#include <string>
#include <vector>

class QTcpSocket;

namespace com::ugcs::ucs::proto {
class Notification;
} // namespace com::ugcs::ucs::proto

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;
class HciRequestDispatcher;

// The server's end of one client connection: decodes requests, hands them to the dispatcher, and
// writes answers, progress and notifications. Answers pass through the test knobs (SimFaults):
// reordering, delay, dropping, malformed frames, disconnecting.
class HciServerConnection : public QObject
{
    Q_OBJECT

public:
    HciServerConnection(QTcpSocket *socket, HciRequestDispatcher &dispatcher, SimFaults &faults, QObject *parent = nullptr);
    ~HciServerConnection() override;

    // The session attached to this connection, or -1.
    int clientId() const { return m_clientId; }
    void setClientId(int id) { m_clientId = id; }
    QString peer() const { return m_peer; }

    void sendAnswer(int32_t instanceId, int32_t requestType, const google::protobuf::Message &answer);
    void sendProgress(int32_t instanceId, const google::protobuf::Message &status);
    void sendNotification(const pb::Notification &notification);
    // Closes the connection at once, as a crash or a cable pull would.
    void drop();
    bool isOpen() const;

signals:
    void closed();

private:
    void onReadyRead();
    void write(const std::string &bytes);
    void release(std::string bytes, int32_t instanceId);
    void flushHeld();
    std::string malformedFrame(int32_t instanceId);

    QTcpSocket *m_socket;
    HciRequestDispatcher &m_dispatcher;
    SimFaults &m_faults;
    hci::HciFrameDecoder m_decoder;
    QString m_peer;
    int m_clientId = -1;
    std::vector<std::string> m_held;
    QTimer m_flushTimer;
    int m_malformedKind = 0;
    bool m_closed = false;
};

} // namespace sortie::sim
