#include "AppSettings.h"

#include "PasswordVault.h"

#include <QSettings>

#include <algorithm>
#include <utility>

namespace sortie::ui {

using secrets::PasswordVault;

namespace {
const QString kServer = QStringLiteral("connection/server");
const QString kUser = QStringLiteral("connection/user");
const QString kRemember = QStringLiteral("connection/rememberPassword");
const QString kPassword = QStringLiteral("connection/password");
const QString kMapSource = QStringLiteral("map/source");
const QString kTemplate = QStringLiteral("map/urlTemplate");
const QString kMbtiles = QStringLiteral("map/mbtiles");
const QString kOrthophoto = QStringLiteral("map/orthophoto");
const QString kOrthophotoOpacity = QStringLiteral("map/orthophotoOpacity");
const QString kDem = QStringLiteral("terrain/demFolder");  // the key ClientGraph reads at start
const QString kUnits = QStringLiteral("display/units");
const QString kLanguage = QStringLiteral("display/language");
const QString kColourScheme = QStringLiteral("display/colourScheme");
const QString kGeometry = QStringLiteral("window/geometry");
const QString kMaximized = QStringLiteral("window/maximized");
} // namespace

AppSettings::AppSettings(QSettings *storage, PasswordVault *vault, QObject *parent)
    : QObject(parent)
    , m_storage(storage)
    , m_vault(vault)
{
    // Older versions kept the password here in plain text. It leaves the file now, whatever comes
    // next: the keyring takes it once it answers, or it is dropped.
    if (m_storage->contains(kPassword)) {
        if (rememberWanted())
            m_plain = PlainPassword{lastServer(), lastUser(), m_storage->value(kPassword).toString()};
        m_storage->remove(kPassword);
        m_storage->sync();
    }
    connect(m_vault, &PasswordVault::stateChanged, this, &AppSettings::keyringChecked);
    connect(m_vault, &PasswordVault::passwordRead, this, [this](const QString &server, const QString &user, const QString &password) {
        if (!rememberPassword() || server != lastServer() || user != lastUser() || password.isEmpty())
            return;
        m_password = password;
        emit passwordChanged();
        emit passwordRecalled();
    });
    connect(m_vault, &PasswordVault::passwordWritten, this, [this] {
        if (std::exchange(m_moving, false))
            setNotice(tr("The password an earlier version kept in the settings file is now in the keyring."));
        else
            setNotice({});
    });
    connect(m_vault, &PasswordVault::failed, this,
            [this](PasswordVault::Operation operation, const QString &, const QString &, const QString &reason) {
        switch (operation) {
        case PasswordVault::Operation::Write:
            // Not kept means not remembered: the box must not claim otherwise.
            write(kRemember, false, &AppSettings::rememberPasswordChanged);
            setNotice(std::exchange(m_moving, false)
                          ? tr("The password an earlier version kept in the settings file was erased from it; the keyring refused it (%1), so it is not remembered.").arg(reason)
                          : tr("The keyring refused the password (%1): it is not remembered.").arg(reason));
            break;
        case PasswordVault::Operation::Read:
            setNotice(tr("The remembered password could not be read from the keyring (%1).").arg(reason));
            break;
        case PasswordVault::Operation::Remove:
            setNotice(tr("The password could not be removed from the keyring (%1).").arg(reason));
            break;
        }
    });
    if (m_vault->state() != PasswordVault::State::Checking)
        keyringChecked();
}

void AppSettings::keyringChecked()
{
    if (m_vault->state() == PasswordVault::State::Available) {
        if (m_plain) {
            const PlainPassword plain = *std::exchange(m_plain, std::nullopt);
            m_moving = true;
            m_vault->write(plain.server, plain.user, plain.password);
            if (plain.server == lastServer() && plain.user == lastUser() && m_password.isEmpty()) {
                m_password = plain.password;
                emit passwordChanged();
                emit passwordRecalled();
            }
        } else if (rememberWanted()) {
            m_vault->read(lastServer(), lastUser());
        }
    } else if (m_vault->state() == PasswordVault::State::Unavailable) {
        QString notice = tr("No keyring is reachable, so the password cannot be remembered (%1).").arg(m_vault->unavailableReason());
        if (std::exchange(m_plain, std::nullopt))
            notice += QLatin1Char(' ') + tr("The password an earlier version kept in the settings file was erased from it.");
        setNotice(notice);
    }
    // Both follow the keyring's state.
    emit canRememberPasswordChanged();
    emit rememberPasswordChanged();
}

void AppSettings::setNotice(const QString &notice)
{
    if (notice == m_notice)
        return;
    m_notice = notice;
    emit passwordNoticeChanged();
}

void AppSettings::write(const QString &key, const QVariant &value, void (AppSettings::*notify)())
{
    if (m_storage->value(key) == value)
        return;
    m_storage->setValue(key, value);
    emit(this->*notify)();
}

QString AppSettings::lastServer() const
{
    return m_storage->value(kServer, QStringLiteral("localhost:3334")).toString();
}

void AppSettings::setLastServer(const QString &server)
{
    write(kServer, server, &AppSettings::lastServerChanged);
}

QString AppSettings::lastUser() const
{
    return m_storage->value(kUser).toString();
}

void AppSettings::setLastUser(const QString &user)
{
    write(kUser, user, &AppSettings::lastUserChanged);
}

bool AppSettings::rememberWanted() const
{
    return m_storage->value(kRemember, false).toBool();
}

bool AppSettings::rememberPassword() const
{
    return rememberWanted() && canRememberPassword();
}

bool AppSettings::canRememberPassword() const
{
    return m_vault->state() == PasswordVault::State::Available;
}

QString AppSettings::passwordNotice() const
{
    return m_notice;
}

void AppSettings::setRememberPassword(bool remember)
{
    if (remember == rememberPassword())
        return;
    if (remember && !canRememberPassword()) {
        emit rememberPasswordChanged(); // a box ticked anyway springs back; passwordNotice says why
        return;
    }
    m_storage->setValue(kRemember, remember);
    if (!remember)
        m_vault->remove(lastServer(), lastUser());
    else if (!m_password.isEmpty())
        m_vault->write(lastServer(), lastUser(), m_password);
    emit rememberPasswordChanged();
}

void AppSettings::setPassword(const QString &password)
{
    if (password == m_password)
        return;
    m_password = password;
    if (rememberPassword() && !m_password.isEmpty())
        m_vault->write(lastServer(), lastUser(), m_password);
    emit passwordChanged();
}

void AppSettings::rememberLogin(const QString &server, const QString &user, const QString &password)
{
    setLastServer(server);
    setLastUser(user);
    const bool differs = password != m_password;
    m_password = password;
    if (differs)
        emit passwordChanged();
}

void AppSettings::loginSucceeded()
{
    // Written on every accepted login, so the keyring holds the password last used for this server and user.
    if (rememberPassword() && !m_password.isEmpty())
        m_vault->write(lastServer(), lastUser(), m_password);
}

QString AppSettings::mapSource() const
{
    const QString source = m_storage->value(kMapSource, QStringLiteral("offline")).toString();
    return source == QLatin1String("xyz") || source == QLatin1String("mbtiles") ? source : QStringLiteral("offline");
}

void AppSettings::setMapSource(const QString &source)
{
    write(kMapSource, source, &AppSettings::mapSourceChanged);
}

QString AppSettings::tileUrlTemplate() const
{
    return m_storage->value(kTemplate, QStringLiteral("https://tile.openstreetmap.org/{z}/{x}/{y}.png")).toString();
}

void AppSettings::setTileUrlTemplate(const QString &urlTemplate)
{
    write(kTemplate, urlTemplate, &AppSettings::tileUrlTemplateChanged);
}

QString AppSettings::mbtilesFile() const
{
    return m_storage->value(kMbtiles).toString();
}

void AppSettings::setMbtilesFile(const QString &file)
{
    write(kMbtiles, file, &AppSettings::mbtilesFileChanged);
}

QString AppSettings::orthophotoFile() const
{
    return m_storage->value(kOrthophoto).toString();
}

void AppSettings::setOrthophotoFile(const QString &file)
{
    write(kOrthophoto, file, &AppSettings::orthophotoFileChanged);
}

double AppSettings::orthophotoOpacity() const
{
    return std::clamp(m_storage->value(kOrthophotoOpacity, 0.8).toDouble(), 0.0, 1.0);
}

void AppSettings::setOrthophotoOpacity(double opacity)
{
    write(kOrthophotoOpacity, std::clamp(opacity, 0.0, 1.0), &AppSettings::orthophotoOpacityChanged);
}

QString AppSettings::demPath() const
{
    return m_storage->value(kDem).toString();
}

void AppSettings::setDemPath(const QString &path)
{
    write(kDem, path, &AppSettings::demPathChanged);
}

QString AppSettings::units() const
{
    return m_storage->value(kUnits, QStringLiteral("metric")).toString();
}

void AppSettings::setUnits(const QString &units)
{
    write(kUnits, units, &AppSettings::unitsChanged);
}

QString AppSettings::language() const
{
    return m_storage->value(kLanguage).toString();
}

void AppSettings::setLanguage(const QString &language)
{
    if (language != this->language())
        write(kLanguage, language, &AppSettings::languageChanged);
}

QString AppSettings::colourScheme() const
{
    return m_storage->value(kColourScheme, QStringLiteral("system")).toString();
}

void AppSettings::setColourScheme(const QString &scheme)
{
    if (scheme != colourScheme())
        write(kColourScheme, scheme, &AppSettings::colourSchemeChanged);
}

QRect AppSettings::windowGeometry() const
{
    return m_storage->value(kGeometry).toRect();
}

void AppSettings::setWindowGeometry(const QRect &geometry)
{
    write(kGeometry, geometry, &AppSettings::windowGeometryChanged);
}

bool AppSettings::windowMaximized() const
{
    return m_storage->value(kMaximized, false).toBool();
}

void AppSettings::setWindowMaximized(bool maximized)
{
    write(kMaximized, maximized, &AppSettings::windowMaximizedChanged);
}

void AppSettings::sync()
{
    m_storage->sync();
}

} // namespace sortie::ui
