#pragma once

#include <QObject>
#include <QString>

namespace QKeychain {
class Job;
}

namespace sortie::secrets {

// Login passwords in the operating system's keyring (the Secret Service on D-Bus: GNOME Keyring,
// KWallet, KeePassXC; through QtKeychain), one entry per server and user. Nothing is ever written
// anywhere else: no keyring, no password kept. Every call is asynchronous (the keyring may have to
// ask the operator to unlock it); results come as signals, in the order the calls were made.
//
// On construction the vault checks that a keyring answers (a read of an entry nobody writes) and
// reports `Available` or `Unavailable` with the keyring's reason.
class PasswordVault : public QObject
{
    Q_OBJECT

public:
    enum class State { Checking, Available, Unavailable };
    Q_ENUM(State)
    enum class Operation { Read, Write, Remove };
    Q_ENUM(Operation)

    // `service` owns the entries in the keyring: "sortie" for the program, another name for tests.
    explicit PasswordVault(const QString &service, QObject *parent = nullptr);
    ~PasswordVault() override;

    State state() const { return m_state; }
    // Why no keyring is reachable, in the keyring library's words; empty unless Unavailable.
    QString unavailableReason() const { return m_reason; }

    // passwordRead (empty when nothing is stored), else failed.
    void read(const QString &server, const QString &user);
    // passwordWritten, else failed.
    void write(const QString &server, const QString &user, const QString &password);
    // passwordRemoved (also when nothing was stored), else failed.
    void remove(const QString &server, const QString &user);

    // The entry's name in the keyring: "hci://user@server", the user percent-encoded so that no two
    // server/user pairs share an entry.
    static QString entryKey(const QString &server, const QString &user);

signals:
    void stateChanged();
    void passwordRead(const QString &server, const QString &user, const QString &password);
    void passwordWritten(const QString &server, const QString &user);
    void passwordRemoved(const QString &server, const QString &user);
    void failed(sortie::secrets::PasswordVault::Operation operation, const QString &server, const QString &user,
                const QString &reason);

private:
    void start(QKeychain::Job *job, Operation operation, const QString &server, const QString &user);
    void finished(QKeychain::Job *job, Operation operation, const QString &server, const QString &user);
    void checked(QKeychain::Job *job);

    QString m_service;
    State m_state = State::Checking;
    QString m_reason;
};

} // namespace sortie::secrets
