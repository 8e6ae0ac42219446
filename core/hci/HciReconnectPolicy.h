#pragma once

#include <chrono>

namespace sortie::hci {

// Exponential backoff between reconnect attempts: initial, then doubled each attempt up to maximum.
// The first attempt after a drop waits `initial`, so a server that restarts is found again quickly
// while a server that stays down is not hammered.
class HciReconnectPolicy
{
public:
    using ms = std::chrono::milliseconds;

    HciReconnectPolicy(ms initial = ms(500), ms maximum = ms(15000));

    void setDelays(ms initial, ms maximum);
    ms initial() const { return m_initial; }
    ms maximum() const { return m_maximum; }

    // The delay before the next attempt; advances the attempt count.
    ms next();
    int attempts() const { return m_attempts; }
    // A connection that drops during the first login (a server restarting) is retried this many times
    // before the operator is told; a session that was ready once retries until closed.
    void setLoginAttempts(int attempts) { m_loginAttempts = attempts < 0 ? 0 : attempts; }
    int loginAttempts() const { return m_loginAttempts; }
    void reset() { m_attempts = 0; }

private:
    ms m_initial;
    ms m_maximum;
    int m_attempts = 0;
    int m_loginAttempts = 6;
};

} // namespace sortie::hci
