#include "SimUsers.h"

namespace sortie::sim {

SimUsers::SimUsers()
    : SimUsers({SimUser{0, QStringLiteral("admin"), QStringLiteral("admin"), true}})
{
}

SimUsers::SimUsers(QList<SimUser> users)
    : m_users(std::move(users))
{
    // Ids are stable by position so that a persisted store keeps pointing at the same users.
    for (int i = 0; i < m_users.size(); ++i)
        if (m_users[i].id <= 0)
            m_users[i].id = i + 1;
}

std::optional<SimUser> SimUsers::parse(const QString &spec)
{
    const qsizetype colon = spec.indexOf(u':');
    if (colon <= 0)
        return std::nullopt;
    return SimUser{0, spec.left(colon), spec.mid(colon + 1), true};
}

std::optional<SimUser> SimUsers::authenticate(const QString &login, const QString &password) const
{
    for (const SimUser &u : m_users)
        if (u.login == login && u.password == password)
            return u;
    return std::nullopt;
}

std::optional<SimUser> SimUsers::find(int id) const
{
    for (const SimUser &u : m_users)
        if (u.id == id)
            return u;
    return std::nullopt;
}

} // namespace sortie::sim
