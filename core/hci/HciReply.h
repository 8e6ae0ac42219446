#pragma once

#include "HciError.h"

#include <QObject>
#include <QTimer>

#include <memory>

namespace sortie::hci {

// One outstanding request, like QNetworkReply: progress while the server works on it (OperationStatus),
// then finished() exactly once, with either the typed response or an HciError. By default the reply
// deletes itself (deleteLater) after finished(); call setAutoDelete(false) to keep it and delete it
// yourself.
class HciReply : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool finished READ isFinished NOTIFY finished)
    Q_PROPERTY(bool ok READ isOk NOTIFY finished)
    Q_PROPERTY(sortie::hci::HciError error READ error NOTIFY finished)

public:
    ~HciReply() override;

    int32_t instanceId() const { return m_instanceId; }
    int32_t requestType() const { return m_requestType; }
    QString requestName() const;

    bool isFinished() const { return m_finished; }
    bool isOk() const { return m_finished && !m_error; }
    const HciError &error() const { return m_error; }

    // The response message, or nullptr until it arrives (or when the request failed).
    const google::protobuf::Message *response() const { return m_response.get(); }
    // The response as its generated type; the type's default instance when there is none or it is
    // another type (check isOk() first).
    template<class T>
    const T &response() const
    {
        const auto *typed = dynamic_cast<const T *>(m_response.get());
        return typed ? *typed : T::default_instance();
    }
    std::unique_ptr<google::protobuf::Message> takeResponse();

    bool autoDelete() const { return m_autoDelete; }
    void setAutoDelete(bool autoDelete) { m_autoDelete = autoDelete; }

signals:
    // OperationStatus from the server: the outermost entry of its progress stack.
    void progress(const QString &title, int value, int maximum);
    void finished();

private:
    friend class HciConnection;
    friend class HciSession;
    HciReply(int32_t instanceId, int32_t requestType, QObject *parent);

    void succeed(std::unique_ptr<google::protobuf::Message> response);
    void fail(const HciError &error);
    // Fails on the next event-loop turn, so a caller connecting to finished() right after send() sees it.
    void failLater(const HciError &error);
    void emitFinished();

    int32_t m_instanceId;
    int32_t m_requestType;
    bool m_finished = false;
    bool m_autoDelete = true;
    HciError m_error;
    std::unique_ptr<google::protobuf::Message> m_response;
    QTimer m_timeout;
};

} // namespace sortie::hci
