#pragma once

#include <QString>

namespace sortie::tls {

class CertificateStore;

// How a link is secured: plain TCP (the default: a real UgCS server and most vehicles speak it), or
// TLS judged by TlsVerdict (the system's trust store, a pinned certificate, else trust on first use
// remembered in `store`). `pinnedSha256` (a fingerprint, from the address or the command line) wins
// over a pin in the store. The store is not owned; without one nothing can be remembered, so only a
// system-trusted or pinned certificate is accepted.
struct TlsOptions
{
    bool enabled = false;
    QString pinnedSha256;
    CertificateStore *store = nullptr;
};

} // namespace sortie::tls
