#include "AppSettings.h"

#include <QSettings>

namespace sortie::ui {

namespace {
const QString kServer = QStringLiteral("connection/server");
const QString kUser = QStringLiteral("connection/user");
const QString kRemember = QStringLiteral("connection/rememberPassword");
const QString kPassword = QStringLiteral("connection/password");
const QString kMapSource = QStringLiteral("map/source");
const QString kTemplate = QStringLiteral("map/urlTemplate");
const QString kMbtiles = QStringLiteral("map/mbtiles");
const QString kUnits = QStringLiteral("display/units");
const QString kGeometry = QStringLiteral("window/geometry");
const QString kMaximized = QStringLiteral("window/maximized");
} // namespace

AppSettings::AppSettings(QSettings *storage, QObject *parent)
    : QObject(parent)
    , m_storage(storage)
{
    if (rememberPassword())
        m_password = m_storage->value(kPassword).toString();
    else
        m_storage->remove(kPassword); // never keep a password nobody asked to remember
}

void AppSettings::write(const QString &key, const QVariant &value)
{
    if (m_storage->value(key) == value)
        return;
    m_storage->setValue(key, value);
    emit changed();
}

QString AppSettings::lastServer() const
{
    return m_storage->value(kServer, QStringLiteral("localhost:3334")).toString();
}

void AppSettings::setLastServer(const QString &server)
{
    write(kServer, server);
}

QString AppSettings::lastUser() const
{
    return m_storage->value(kUser).toString();
}

void AppSettings::setLastUser(const QString &user)
{
    write(kUser, user);
}

bool AppSettings::rememberPassword() const
{
    return m_storage->value(kRemember, false).toBool();
}

void AppSettings::setRememberPassword(bool remember)
{
    if (remember == rememberPassword())
        return;
    m_storage->setValue(kRemember, remember);
    if (remember)
        m_storage->setValue(kPassword, m_password);
    else
        m_storage->remove(kPassword);
    emit changed();
}

void AppSettings::setPassword(const QString &password)
{
    if (password == m_password)
        return;
    m_password = password;
    if (rememberPassword())
        m_storage->setValue(kPassword, m_password);
    emit changed();
}

QString AppSettings::mapSource() const
{
    const QString source = m_storage->value(kMapSource, QStringLiteral("offline")).toString();
    return source == QLatin1String("xyz") || source == QLatin1String("mbtiles") ? source : QStringLiteral("offline");
}

void AppSettings::setMapSource(const QString &source)
{
    write(kMapSource, source);
}

QString AppSettings::tileUrlTemplate() const
{
    return m_storage->value(kTemplate, QStringLiteral("https://tile.openstreetmap.org/{z}/{x}/{y}.png")).toString();
}

void AppSettings::setTileUrlTemplate(const QString &urlTemplate)
{
    write(kTemplate, urlTemplate);
}

QString AppSettings::mbtilesFile() const
{
    return m_storage->value(kMbtiles).toString();
}

void AppSettings::setMbtilesFile(const QString &file)
{
    write(kMbtiles, file);
}

QString AppSettings::units() const
{
    return m_storage->value(kUnits, QStringLiteral("metric")).toString();
}

void AppSettings::setUnits(const QString &units)
{
    write(kUnits, units);
}

QRect AppSettings::windowGeometry() const
{
    return m_storage->value(kGeometry).toRect();
}

void AppSettings::setWindowGeometry(const QRect &geometry)
{
    write(kGeometry, geometry);
}

bool AppSettings::windowMaximized() const
{
    return m_storage->value(kMaximized, false).toBool();
}

void AppSettings::setWindowMaximized(bool maximized)
{
    write(kMaximized, maximized);
}

void AppSettings::sync()
{
    m_storage->sync();
}

} // namespace sortie::ui
