#pragma once

#include "CertificateStore.h"
#include "CleartextConsent.h"
#include "HciError.h"
#include "HciSession.h"
#include "ServerAddress.h"
#include "TlsVerdict.h"

#include <QObject>
#include <QPointer>

#include <optional>

class QSettings;

namespace sortie::client {

// The connection as the Login view and the status bar see it: the session's state by name
// (Disconnected, Connecting, Authorizing, LoggingIn, Ready, Reconnecting), whether a login is
// under way, and the last failure in words an operator can act on. The session (not owned)
// does the work; this class checks the operator's input and explains the outcome. It decides how the
// password travels: over TLS for tls://host:port (certificates judged by tls::TlsVerdict against
// the settings' CertificateStore), else in clear, after asking the operator once per server when the
// server is not this computer (CleartextConsent).
class ConnectionController : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QString state READ stateName NOTIFY stateChanged)
    Q_PROPERTY(bool busy READ isBusy NOTIFY stateChanged)
    Q_PROPERTY(bool ready READ isReady NOTIFY stateChanged)
    Q_PROPERTY(QString server READ server NOTIFY stateChanged)
    Q_PROPERTY(QString user READ user NOTIFY stateChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY errorChanged)
    Q_PROPERTY(QString errorKind READ errorKind NOTIFY errorChanged)
    Q_PROPERTY(QString detail READ detail NOTIFY detailChanged)
    // What the status bar says after the state: the detail when there is one, else "user at server"
    // once ready, else nothing.
    Q_PROPERTY(QString statusDetail READ statusDetail NOTIFY statusDetailChanged)
    // The state in the operator's words ("Ready", "Bereit"): `state` stays the key views compare.
    Q_PROPERTY(QString stateText READ stateText NOTIFY stateTextChanged)
    // True while the operator is asked whether the password may go to `server` in clear; the
    // question in words, and the answer through answerCleartext().
    Q_PROPERTY(bool askingCleartext READ isAskingCleartext NOTIFY cleartextQuestionChanged)
    Q_PROPERTY(QString cleartextQuestion READ cleartextQuestion NOTIFY cleartextQuestionChanged)
    // Over TLS: how the server's certificate was trusted and its SHA-256 fingerprint (on first use,
    // that it is now remembered); empty for a plain connection.
    Q_PROPERTY(QString certificateNote READ certificateNote NOTIFY certificateNoteChanged)

public:
    // `settings` (not owned; may be null: nothing remembered) keep the certificates and the answers.
    explicit ConnectionController(hci::HciSession *session, QSettings *settings = nullptr, QObject *parent = nullptr);

    hci::HciSession *session() const { return m_session; }
    QString stateName() const;
    bool isBusy() const;
    bool isReady() const { return m_session && m_session->isReady(); }
    QString server() const { return m_server; }
    QString user() const { return m_user; }
    QString errorString() const { return m_errorString; }
    QString errorKind() const { return m_errorKind; }
    QString detail() const { return m_detail; }
    QString statusDetail() const;
    QString stateText() const;
    bool isAskingCleartext() const { return m_pending.has_value(); }
    QString cleartextQuestion() const;
    QString certificateNote() const { return m_certificateNote; }
    tls::CertificateStore &certificates() { return m_certificates; }

    // Checks the input and starts logging in (or asks first: askingCleartext); false (with
    // errorString) when the input is wrong.
    Q_INVOKABLE bool connectToServer(const QString &server, const QString &user, const QString &password);
    Q_INVOKABLE void disconnectFromServer();
    // The operator's answer: true sends the password in clear (and remembers that for this server),
    // false gives the login up.
    Q_INVOKABLE void answerCleartext(bool sendInClear);
    // The login page's "Secure" choice on the address as typed: whether it says tls://, and the
    // address with it added or taken off.
    Q_INVOKABLE bool isSecureAddress(const QString &server) const;
    Q_INVOKABLE QString withSecurity(const QString &server, bool secure) const;

    // What to tell the operator about a failed connection.
    static QString explain(const hci::HciError &error);

signals:
    void stateChanged();
    void errorChanged();
    void detailChanged();
    void statusDetailChanged();
    void stateTextChanged();
    void cleartextQuestionChanged();
    void certificateNoteChanged();
    void ready();

private:
    void setError(const QString &kind, const QString &message);
    void setDetail(const QString &detail);
    void open(const ServerAddress &target, const QString &user, const QString &password);
    void onCertificateAccepted(const tls::TlsVerdict &verdict);
    void setCertificateNote(const QString &note);

    struct PendingLogin
    {
        ServerAddress target;
        QString user;
        QString password; // held only until the operator answers; never logged
    };

    QPointer<hci::HciSession> m_session;
    tls::CertificateStore m_certificates;
    CleartextConsent m_consent;
    std::optional<PendingLogin> m_pending;
    QString m_certificateNote;
    QString m_server;
    QString m_user;
    QString m_errorString;
    QString m_errorKind;
    QString m_detail;
};

} // namespace sortie::client
