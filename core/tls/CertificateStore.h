#pragma once

#include <QString>

#include <optional>

class QSettings;

namespace sortie::tls {

// The certificates trusted per server ("host:port", as the operator's address names it), kept in
// the operator's settings: a pinned one (the only certificate that server may show) and the one
// remembered on first use. Fingerprints are SHA-256 in colon-hex (CertificateFingerprint.h). The
// settings (not owned) must outlive the store.
class CertificateStore
{
public:
    explicit CertificateStore(QSettings *settings);

    std::optional<QString> pinned(const QString &peer) const;
    // False when `fingerprint` is not a SHA-256 fingerprint.
    bool pin(const QString &peer, const QString &fingerprint);
    void unpin(const QString &peer);

    std::optional<QString> remembered(const QString &peer) const;
    void remember(const QString &peer, const QString &fingerprint);
    // The operator's way out after a server's certificate was replaced on purpose.
    void forget(const QString &peer);

private:
    std::optional<QString> read(const QString &key) const;

    QSettings *m_settings;
};

} // namespace sortie::tls
