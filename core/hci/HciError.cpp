#include "HciError.h"

#include "Messages.pb.h"

#include <QMetaEnum>
#include <QCoreApplication>

namespace sortie::hci {

HciError::HciError(Kind kind, QString message, int code)
    : m_kind(kind)
    , m_message(std::move(message))
    , m_code(code)
{
}

HciError HciError::fromServer(const pb::Error &error)
{
    HciError e;
    e.m_kind = Kind::Server;
    e.m_code = error.has_errorcode() ? error.errorcode() : 0;
    e.m_suppressible = error.issuppressible();
    e.m_message = QString::fromStdString(error.errormessage());
    if (error.has_errordetail())
        e.m_detail = std::make_shared<const pb::ErrorDetailWrapper>(error.errordetail());

    const auto &detail = error.errordetail();
    if (e.m_code == kLicenceConstraintCode || detail.has_licenseconstrainterrordetail()) {
        e.m_kind = Kind::Licence;
        if (e.m_message.isEmpty()) {
            const auto &licence = detail.licenseconstrainterrordetail();
            e.m_message = licence.has_permission()
                ? QCoreApplication::translate("HciError", "The server's licence does not allow this (%1)").arg(QString::fromStdString(licence.permission()))
                : QCoreApplication::translate("HciError", "The server's licence does not allow this");
        }
    } else if (detail.has_unsupportedprotocolversiondetail()) {
        e.m_kind = Kind::Version;
        const auto &server = detail.unsupportedprotocolversiondetail().serverversion();
        const QString version = QStringLiteral("%1.%2").arg(server.major()).arg(server.minor());
        e.m_message = QCoreApplication::translate("HciError", "The server speaks HCI protocol %1; Sortie speaks 2.0%2")
                          .arg(version, e.m_message.isEmpty() ? QString() : QStringLiteral(" (") + e.m_message + u')');
    }
    if (e.m_message.isEmpty())
        e.m_message = e.m_code ? QCoreApplication::translate("HciError", "The server refused the request (error %1)").arg(e.m_code)
                               : QCoreApplication::translate("HciError", "The server refused the request without a reason");
    return e;
}

HciError HciError::as(Kind kind, const QString &message) const
{
    HciError e = *this;
    e.m_kind = kind;
    e.m_message = message;
    return e;
}

QString HciError::kindName(Kind kind)
{
    return QString::fromLatin1(QMetaEnum::fromType<Kind>().valueToKey(int(kind)));
}

QString HciError::toString() const
{
    if (!isError())
        return QCoreApplication::translate("HciError", "no error");
    QString s = kindName(m_kind) + QStringLiteral(": ") + m_message;
    if (m_code)
        s += QCoreApplication::translate("HciError", " (code %1)").arg(m_code);
    return s;
}

} // namespace sortie::hci
