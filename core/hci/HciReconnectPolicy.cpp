#include "HciReconnectPolicy.h"

#include <algorithm>

namespace sortie::hci {

HciReconnectPolicy::HciReconnectPolicy(ms initial, ms maximum)
{
    setDelays(initial, maximum);
}

void HciReconnectPolicy::setDelays(ms initial, ms maximum)
{
    m_initial = std::max(initial, ms(1));
    m_maximum = std::max(maximum, m_initial);
}

HciReconnectPolicy::ms HciReconnectPolicy::next()
{
    ms delay = m_initial;
    for (int i = 0; i < m_attempts && delay < m_maximum; ++i)
        delay *= 2;
    ++m_attempts;
    return std::min(delay, m_maximum);
}

} // namespace sortie::hci
