#include "ConnectionController.h"

#include "HciConnection.h"
#include "LanguageChange.h"
#include "ServerAddress.h"

#include <QMetaEnum>

namespace sortie::client {

using hci::HciError;
using hci::HciSession;

ConnectionController::ConnectionController(HciSession *session, QSettings *settings, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_certificates(settings)
    , m_consent(settings)
{
    connect(session->connection(), &hci::HciConnection::certificateAccepted, this, &ConnectionController::onCertificateAccepted);
    connect(this, &ConnectionController::stateChanged, this, &ConnectionController::statusDetailChanged);
    connect(this, &ConnectionController::detailChanged, this, &ConnectionController::statusDetailChanged);
    connect(this, &ConnectionController::stateChanged, this, &ConnectionController::stateTextChanged);
    // The state's words and "user at server" are worded as read: a language change re-reads them.
    i18n::onLanguageChange(this, [this] {
        emit stateTextChanged();
        emit statusDetailChanged();
        emit cleartextQuestionChanged();
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
    setError({}, {});
    if (m_consent.mustAsk(target)) {
        m_pending = PendingLogin{target, user.trimmed(), password};
        emit cleartextQuestionChanged();
        return true;
    }
    open(target, user.trimmed(), password);
    return true;
}

void ConnectionController::open(const ServerAddress &target, const QString &user, const QString &password)
{
    m_server = target.toString();
    m_user = user;
    setCertificateNote({});
    m_session->open(target.host, target.port, m_user, password, tls::TlsOptions{target.tls, {}, &m_certificates});
    emit stateChanged();
}

QString ConnectionController::cleartextQuestion() const
{
    if (!m_pending)
        return {};
    return tr("%1 is not this computer, and this connection is not secured: the password for %2 would cross the network "
              "in clear, readable by anyone on the way, at every login and reconnect. Send it in clear to this server? "
              "(Choose Secure if the server is behind a TLS terminator.)")
        .arg(m_pending->target.peer(), m_pending->user);
}

void ConnectionController::answerCleartext(bool sendInClear)
{
    if (!m_pending)
        return;
    PendingLogin login = std::move(*m_pending);
    m_pending.reset();
    emit cleartextQuestionChanged();
    if (!sendInClear) {
        setError(QStringLiteral("Cleartext"), tr("Not connected to %1: the password was not sent.").arg(login.target.peer()));
        return;
    }
    m_consent.allow(login.target);
    open(login.target, login.user, login.password);
}

bool ConnectionController::isSecureAddress(const QString &server) const
{
    return server.trimmed().startsWith(QLatin1String("tls://"), Qt::CaseInsensitive);
}

QString ConnectionController::withSecurity(const QString &server, bool secure) const
{
    QString bare = server.trimmed();
    if (isSecureAddress(bare))
        bare = bare.mid(6);
    return secure ? QStringLiteral("tls://") + bare : bare;
}

void ConnectionController::onCertificateAccepted(const tls::TlsVerdict &verdict)
{
    using Basis = tls::TlsVerdict::Basis;
    const QString peer = m_session ? m_session->connection()->peerName() : QString();
    switch (verdict.basis) {
    case Basis::FirstUse:
        setCertificateNote(tr("First secure connection to %1: its certificate is now trusted for this server and remembered. "
                              "Compare its SHA-256 fingerprint with the server's: %2").arg(peer, verdict.fingerprint));
        return;
    case Basis::Remembered:
        setCertificateNote(tr("Secured by TLS: the certificate remembered for %1 (SHA-256 %2).").arg(peer, verdict.fingerprint));
        return;
    case Basis::Pinned:
        setCertificateNote(tr("Secured by TLS: the certificate pinned for %1 (SHA-256 %2).").arg(peer, verdict.fingerprint));
        return;
    case Basis::System:
        setCertificateNote(tr("Secured by TLS: a certificate this computer trusts (SHA-256 %1).").arg(verdict.fingerprint));
        return;
    case Basis::Refused:
        break;
    }
}

void ConnectionController::setCertificateNote(const QString &note)
{
    if (note == m_certificateNote)
        return;
    m_certificateNote = note;
    emit certificateNoteChanged();
}

void ConnectionController::disconnectFromServer()
{
    if (m_pending)
        answerCleartext(false);
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
    case HciError::Kind::Certificate:
        return tr("%1. The password was not sent.").arg(what);
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
