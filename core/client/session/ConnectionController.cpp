#include "ConnectionController.h"

#include "LanguageChange.h"
#include "ServerAddress.h"

#include <QMetaEnum>

namespace sortie::client {

using hci::HciError;
using hci::HciSession;

ConnectionController::ConnectionController(HciSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{
    connect(this, &ConnectionController::stateChanged, this, &ConnectionController::statusDetailChanged);
    connect(this, &ConnectionController::detailChanged, this, &ConnectionController::statusDetailChanged);
    connect(this, &ConnectionController::stateChanged, this, &ConnectionController::stateTextChanged);
    // The state's words and "user at server" are worded as read: a language change re-reads them.
    i18n::onLanguageChange(this, [this] {
        emit stateTextChanged();
        emit statusDetailChanged();
    });
    connect(session, &HciSession::stateChanged, this, [this](HciSession::State state) {
        if (state == HciSession::State::Ready || state == HciSession::State::Disconnected)
            setDetail({});
        emit stateChanged();
    });
    connect(session, &HciSession::ready, this, [this] {
        setError({}, {});
        emit ready();
    });
    connect(session, &HciSession::errorOccurred, this, [this](const HciError &error) {
        setError(HciError::kindName(error.kind()), explain(error));
    });
    connect(session, &HciSession::reconnectScheduled, this, [this](int attempt, int delayMs) {
        setDetail(tr("connection lost; attempt %1 in %2 s").arg(attempt).arg(delayMs / 1000.0, 0, 'f', 1));
    });
    connect(session, &HciSession::resumed, this, [this](bool sameSession) {
        setDetail(sameSession ? QString() : tr("reconnected in a new session"));
    });
}

QString ConnectionController::statusDetail() const
{
    if (!m_detail.isEmpty())
        return m_detail;
    return isReady() ? tr("%1 at %2").arg(m_user, m_server) : QString();
}

QString ConnectionController::stateName() const
{
    if (!m_session)
        return QStringLiteral("Disconnected");
    return QString::fromLatin1(QMetaEnum::fromType<HciSession::State>().valueToKey(int(m_session->state())));
}

QString ConnectionController::stateText() const
{
    if (!m_session)
        return tr("Disconnected");
    switch (m_session->state()) {
    case HciSession::State::Disconnected: return tr("Disconnected");
    case HciSession::State::Connecting: return tr("Connecting");
    case HciSession::State::Authorizing: return tr("Authorizing");
    case HciSession::State::LoggingIn: return tr("Logging in");
    case HciSession::State::Ready: return tr("Ready");
    case HciSession::State::Reconnecting: return tr("Reconnecting");
    }
    return stateName();
}

bool ConnectionController::isBusy() const
{
    if (!m_session)
        return false;
    const HciSession::State state = m_session->state();
    return state == HciSession::State::Connecting || state == HciSession::State::Authorizing
           || state == HciSession::State::LoggingIn;
}

bool ConnectionController::connectToServer(const QString &server, const QString &user, const QString &password)
{
    if (!m_session)
        return false;
    const auto address = ServerAddress::parse(server);
    if (const auto *problem = std::get_if<QString>(&address)) {
        setError(QStringLiteral("Input"), tr("The server address is not usable: %1.").arg(*problem));
        return false;
    }
    if (user.trimmed().isEmpty()) {
        setError(QStringLiteral("Input"), tr("Enter a user name."));
        return false;
    }
    const ServerAddress target = std::get<ServerAddress>(address);
    m_server = target.toString();
    m_user = user.trimmed();
    setError({}, {});
    m_session->open(target.host, target.port, m_user, password);
    emit stateChanged();
    return true;
}

void ConnectionController::disconnectFromServer()
{
    if (m_session)
        m_session->close();
}

QString ConnectionController::explain(const HciError &error)
{
    const QString what = error.message();
    switch (error.kind()) {
    case HciError::Kind::Unreachable:
        return tr("%1. Check the server's address and this computer's network.").arg(what);
    case HciError::Kind::Refused:
        return tr("%1. Is the UgCS server running, and is the port right?").arg(what);
    case HciError::Kind::Authentication:
        return tr("Wrong user name or password (%1).").arg(what);
    case HciError::Kind::Version:
        return tr("%1. This server cannot be used with Sortie.").arg(what);
    case HciError::Kind::Licence:
        return tr("The server's licence allows no more connections (%1). Close another client or extend the licence.").arg(what);
    case HciError::Kind::Timeout:
        return tr("The server did not answer in time (%1). It may be overloaded or not a UgCS server.").arg(what);
    case HciError::Kind::Disconnected:
        return tr("The connection was closed (%1).").arg(what);
    case HciError::Kind::Protocol:
        return tr("The server answered something Sortie cannot use (%1).").arg(what);
    case HciError::Kind::Server:
        return tr("The server refused: %1").arg(what);
    case HciError::Kind::Cancelled:
    case HciError::Kind::None:
        break;
    }
    return what;
}

void ConnectionController::setError(const QString &kind, const QString &message)
{
    if (kind == m_errorKind && message == m_errorString)
        return;
    m_errorKind = kind;
    m_errorString = message;
    emit errorChanged();
}

void ConnectionController::setDetail(const QString &detail)
{
    if (detail == m_detail)
        return;
    m_detail = detail;
    emit detailChanged();
}

} // namespace sortie::client
