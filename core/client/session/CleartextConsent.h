#pragma once

#include "ServerAddress.h"

#include <QString>

class QSettings;

namespace sortie::client {

// Whether the operator must be asked before a password goes to a server in clear: not over TLS and
// not this computer (ServerAddress::isLoopback), unless the operator already said yes for that
// server (host:port), which the settings remember. A "no" is not remembered: the next try asks again.
class CleartextConsent
{
public:
    explicit CleartextConsent(QSettings *settings); // not owned; nullptr: nothing remembered

    bool mustAsk(const ServerAddress &address) const;
    void allow(const ServerAddress &address);
    bool allowed(const ServerAddress &address) const;

private:
    QSettings *m_settings;
};

} // namespace sortie::client
