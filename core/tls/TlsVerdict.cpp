#include "TlsVerdict.h"

#include "CertificateFingerprint.h"
#include "CertificateStore.h"
#include "TlsLog.h"

#include <QCoreApplication>
#include <QSslError>
#include <QStringList>

namespace sortie::tls {
namespace {

QString errorsOf(const QList<QSslError> &errors)
{
    QStringList words;
    for (const QSslError &e : errors)
        if (!words.contains(e.errorString()))
            words << e.errorString();
    return words.join(QStringLiteral("; "));
}

TlsVerdict refused(const QString &fingerprint, const QString &reason)
{
    qCWarning(lcTls).noquote() << "certificate refused:" << reason;
    return {TlsVerdict::Basis::Refused, fingerprint, reason};
}

} // namespace

TlsVerdict TlsVerdict::judge(const TlsOptions &options, const QString &peer, const QString &hostName,
                             const QList<QSslCertificate> &chain)
{
    if (chain.isEmpty() || chain.first().isNull())
        return refused({}, QCoreApplication::translate("TlsVerdict", "%1 sent no certificate").arg(peer));
    const QString fingerprint = sha256Fingerprint(chain.first());

    std::optional<QString> pin;
    if (!options.pinnedSha256.isEmpty()) {
        pin = normalizedFingerprint(options.pinnedSha256);
        if (!pin)
            return refused(fingerprint, QCoreApplication::translate("TlsVerdict", "the pinned fingerprint for %1 is not a SHA-256 fingerprint (64 hex digits): %2")
                                            .arg(peer, options.pinnedSha256));
    } else if (options.store) {
        pin = options.store->pinned(peer);
    }
    if (pin) {
        if (*pin != fingerprint)
            return refused(fingerprint, QCoreApplication::translate("TlsVerdict", "%1 showed a certificate that is not the pinned one: pinned SHA-256 %2, shown SHA-256 %3")
                                            .arg(peer, *pin, fingerprint));
        qCInfo(lcTls).noquote() << peer << "showed its pinned certificate";
        return {Basis::Pinned, fingerprint, {}};
    }

    const QList<QSslError> errors = QSslCertificate::verify(chain, hostName);
    if (errors.isEmpty()) {
        qCInfo(lcTls).noquote() << peer << "certificate trusted by the system, SHA-256" << fingerprint;
        return {Basis::System, fingerprint, {}};
    }

    const auto known = options.store ? options.store->remembered(peer) : std::nullopt;
    if (known) {
        if (*known != fingerprint)
            return refused(fingerprint, QCoreApplication::translate("TlsVerdict",
                                                                    "the certificate of %1 has changed since it was first trusted: remembered SHA-256 %2, now SHA-256 %3. "
                                                                    "Someone may be in between; if the server's certificate was replaced on purpose, forget the remembered one")
                                            .arg(peer, *known, fingerprint));
        qCInfo(lcTls).noquote() << peer << "showed its remembered certificate";
        return {Basis::Remembered, fingerprint, {}};
    }
    if (!options.store)
        return refused(fingerprint, QCoreApplication::translate("TlsVerdict", "the certificate of %1 (SHA-256 %2) is not trusted by this system (%3), and there is no pinned or remembered one")
                                        .arg(peer, fingerprint, errorsOf(errors)));
    options.store->remember(peer, fingerprint);
    qCInfo(lcTls).noquote() << peer << "trusted on first use, SHA-256" << fingerprint << "(not trusted by the system:" << errorsOf(errors) << ")";
    return {Basis::FirstUse, fingerprint, {}};
}

} // namespace sortie::tls
