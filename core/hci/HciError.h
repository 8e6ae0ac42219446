#pragma once

#include "HciProto.h"

#include <QMetaType>
#include <QString>

#include <memory>

namespace sortie::hci {

// What went wrong with a request or a session, as a value: a kind a program can branch on and a
// message an operator can read. Server errors keep UgCS's code, suppressible flag and detail.
class HciError
{
    Q_GADGET
    Q_PROPERTY(Kind kind READ kind)
    Q_PROPERTY(QString message READ message)
    Q_PROPERTY(int code READ code)
    Q_PROPERTY(bool suppressible READ suppressible)
    Q_PROPERTY(bool isError READ isError)

public:
    enum class Kind {
        None,           // no error
        Server,         // the server answered with Error (type 0)
        Timeout,        // no answer within the request's timeout
        Disconnected,   // the connection closed before the answer came, or there was none
        Protocol,       // an answer we cannot use (wrong type), or a request we cannot encode
        Unreachable,    // the host cannot be found or reached
        Refused,        // nothing listens on that port
        Authentication, // bad login or password
        Version,        // the server does not speak our protocol version
        Licence,        // the server's licence forbids it (UgCS error code 1001)
        Cancelled,      // the caller gave up (session closed)
        Certificate,    // TLS: the server's certificate is not trusted (nothing was sent to it)
    };
    Q_ENUM(Kind)

    // UgCS error code for licence constraints.
    static constexpr int kLicenceConstraintCode = 1001;

    HciError() = default;
    HciError(Kind kind, QString message, int code = 0);
    // Classifies a server Error: licence code 1001 and a protocol-version detail get their own kinds.
    static HciError fromServer(const pb::Error &error);

    Kind kind() const { return m_kind; }
    QString message() const { return m_message; }
    int code() const { return m_code; }
    bool suppressible() const { return m_suppressible; }
    bool isError() const { return m_kind != Kind::None; }
    explicit operator bool() const { return isError(); }
    // The server's ErrorDetailWrapper, or nullptr when it sent none.
    const pb::ErrorDetailWrapper *detail() const { return m_detail.get(); }

    // The same error seen from a higher level, e.g. a server error on login becomes Authentication.
    HciError as(Kind kind, const QString &message) const;
    // "Timeout: No answer to LoginRequest within 30 s" style text for logs.
    QString toString() const;
    static QString kindName(Kind kind);

private:
    Kind m_kind = Kind::None;
    QString m_message;
    int m_code = 0;
    bool m_suppressible = false;
    std::shared_ptr<const pb::ErrorDetailWrapper> m_detail;
};

} // namespace sortie::hci

Q_DECLARE_METATYPE(sortie::hci::HciError)
