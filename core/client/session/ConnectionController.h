#pragma once

#include "HciError.h"
#include "HciSession.h"

#include <QObject>
#include <QPointer>

namespace sortie::client {

// The connection as the Login view and the status bar see it: the session's state by name
// (Disconnected, Connecting, Authorizing, LoggingIn, Ready, Reconnecting), whether a login is
// under way, and the last failure in words an operator can act on. The session (not owned)
// does the work; this class checks the operator's input and explains the outcome.
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

public:
    explicit ConnectionController(hci::HciSession *session, QObject *parent = nullptr);

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

    // Checks the input and starts logging in; false (with errorString) when the input is wrong.
    Q_INVOKABLE bool connectToServer(const QString &server, const QString &user, const QString &password);
    Q_INVOKABLE void disconnectFromServer();

    // What to tell the operator about a failed connection.
    static QString explain(const hci::HciError &error);

signals:
    void stateChanged();
    void errorChanged();
    void detailChanged();
    void statusDetailChanged();
    void stateTextChanged();
    void ready();

private:
    void setError(const QString &kind, const QString &message);
    void setDetail(const QString &detail);

    QPointer<hci::HciSession> m_session;
    QString m_server;
    QString m_user;
    QString m_errorString;
    QString m_errorKind;
    QString m_detail;
};

} // namespace sortie::client
