#pragma once

#include <QList>
#include <QString>

#include <optional>

namespace sortie::sim {

// The simulator's accounts (admin/admin unless configured). Passwords are compared, never logged.
struct SimUser
{
    int id = 0;
    QString login;
    QString password;
    bool administrator = true;
};

class SimUsers
{
public:
    SimUsers();                          // admin/admin
    explicit SimUsers(QList<SimUser> users);

    // Parses "login:password" (the password may contain ':'); nullopt when malformed.
    static std::optional<SimUser> parse(const QString &spec);

    std::optional<SimUser> authenticate(const QString &login, const QString &password) const;
    std::optional<SimUser> find(int id) const;
    const QList<SimUser> &all() const { return m_users; }

private:
    QList<SimUser> m_users;
};

} // namespace sortie::sim
