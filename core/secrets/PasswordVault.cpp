#include "PasswordVault.h"

#include "SecretsLog.h"

#include <QUrl>
#include <qt6keychain/keychain.h>

namespace sortie::secrets {

namespace {
// An entry Sortie never writes: reading it tells whether a keyring answers, without touching a
// real entry (and so without an unlock prompt for one).
const QString kProbeKey = QStringLiteral("sortie-keyring-check");

// Errors that mean "there is a keyring, it just holds nothing here".
bool meansEmpty(QKeychain::Error error)
{
    return error == QKeychain::EntryNotFound;
}
} // namespace

PasswordVault::PasswordVault(const QString &service, QObject *parent)
    : QObject(parent)
    , m_service(service)
{
    auto *job = new QKeychain::ReadPasswordJob(m_service);
    job->setKey(kProbeKey);
    connect(job, &QKeychain::Job::finished, this, &PasswordVault::checked);
    job->start();
}

// Jobs are not children of the vault: QtKeychain's backends call back into a job that has started,
// so a job must live until it finishes (it deletes itself then). Their results are delivered to the
// vault only while it exists.
PasswordVault::~PasswordVault() = default;

QString PasswordVault::entryKey(const QString &server, const QString &user)
{
    return QStringLiteral("hci://%1@%2").arg(QString::fromLatin1(QUrl::toPercentEncoding(user)), server);
}

void PasswordVault::checked(QKeychain::Job *job)
{
    if (job->error() == QKeychain::NoError || meansEmpty(job->error())) {
        m_state = State::Available;
        qCInfo(lcSecrets) << "keyring reachable for" << m_service;
    } else {
        m_state = State::Unavailable;
        m_reason = job->errorString().isEmpty() ? tr("the keyring did not answer") : job->errorString();
        qCInfo(lcSecrets) << "no keyring reachable:" << m_reason;
    }
    emit stateChanged();
}

void PasswordVault::read(const QString &server, const QString &user)
{
    start(new QKeychain::ReadPasswordJob(m_service), Operation::Read, server, user);
}

void PasswordVault::write(const QString &server, const QString &user, const QString &password)
{
    auto *job = new QKeychain::WritePasswordJob(m_service);
    job->setTextData(password);
    start(job, Operation::Write, server, user);
}

void PasswordVault::remove(const QString &server, const QString &user)
{
    start(new QKeychain::DeletePasswordJob(m_service), Operation::Remove, server, user);
}

void PasswordVault::start(QKeychain::Job *job, Operation operation, const QString &server, const QString &user)
{
    job->setKey(entryKey(server, user));
    job->setInsecureFallback(false); // QtKeychain's fallback is a plain settings file: never
    connect(job, &QKeychain::Job::finished, this,
            [this, operation, server, user](QKeychain::Job *done) { finished(done, operation, server, user); });
    job->start();
}

void PasswordVault::finished(QKeychain::Job *job, Operation operation, const QString &server, const QString &user)
{
    const QString key = job->key();
    if (job->error() != QKeychain::NoError && !meansEmpty(job->error())) {
        qCWarning(lcSecrets) << operation << key << "failed:" << job->errorString();
        emit failed(operation, server, user, job->errorString());
        return;
    }
    qCDebug(lcSecrets) << operation << key << (meansEmpty(job->error()) ? "(no entry)" : "done");
    switch (operation) {
    case Operation::Read:
        emit passwordRead(server, user, static_cast<QKeychain::ReadPasswordJob *>(job)->textData());
        break;
    case Operation::Write:
        emit passwordWritten(server, user);
        break;
    case Operation::Remove:
        emit passwordRemoved(server, user);
        break;
    }
}

} // namespace sortie::secrets
