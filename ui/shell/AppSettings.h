#pragma once

#include <QObject>
#include <QRect>
#include <QtQml/qqmlregistration.h>

#include <optional>

class QSettings;

namespace sortie::secrets {
class PasswordVault;
}

namespace sortie::ui {

// What the operator chose last time, kept in QSettings: server, user, "remember the password",
// window geometry, map source, units, language and colour scheme. The password itself never goes into the settings: it is
// held in memory for the session and, while `rememberPassword` is on, kept in the operating
// system's keyring by the vault, under the last server and user; turning "remember" off removes it
// from there. Without a reachable keyring nothing is remembered (`canRememberPassword` is false and
// `passwordNotice` says why). A plain-text password left in the settings by an older version is
// moved to the keyring and erased from the file at start. Nothing here is logged.
class AppSettings : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("AppSettings is created by the application")
    Q_PROPERTY(QString lastServer READ lastServer WRITE setLastServer NOTIFY lastServerChanged)
    Q_PROPERTY(QString lastUser READ lastUser WRITE setLastUser NOTIFY lastUserChanged)
    Q_PROPERTY(bool rememberPassword READ rememberPassword WRITE setRememberPassword NOTIFY rememberPasswordChanged)
    Q_PROPERTY(QString password READ password WRITE setPassword NOTIFY passwordChanged)
    Q_PROPERTY(bool canRememberPassword READ canRememberPassword NOTIFY canRememberPasswordChanged)
    Q_PROPERTY(QString passwordNotice READ passwordNotice NOTIFY passwordNoticeChanged)
    Q_PROPERTY(QString mapSource READ mapSource WRITE setMapSource NOTIFY mapSourceChanged)
    Q_PROPERTY(QString tileUrlTemplate READ tileUrlTemplate WRITE setTileUrlTemplate NOTIFY tileUrlTemplateChanged)
    Q_PROPERTY(QString mbtilesFile READ mbtilesFile WRITE setMbtilesFile NOTIFY mbtilesFileChanged)
    // The operator's own rasters (docs/rasters.md): an orthophoto over the base map, and a DEM file or
    // folder (the setting terrain/demFolder the terrain reads; empty: none).
    Q_PROPERTY(QString orthophotoFile READ orthophotoFile WRITE setOrthophotoFile NOTIFY orthophotoFileChanged)
    Q_PROPERTY(double orthophotoOpacity READ orthophotoOpacity WRITE setOrthophotoOpacity NOTIFY orthophotoOpacityChanged)
    Q_PROPERTY(QString demPath READ demPath WRITE setDemPath NOTIFY demPathChanged)
    Q_PROPERTY(QString units READ units WRITE setUnits NOTIFY unitsChanged)
    Q_PROPERTY(QString language READ language WRITE setLanguage NOTIFY languageChanged)
    // The theme's scheme: "system" (the default), "light", "dark" or "sunlight" (Theme::schemeFromName).
    Q_PROPERTY(QString colourScheme READ colourScheme WRITE setColourScheme NOTIFY colourSchemeChanged)
    Q_PROPERTY(QRect windowGeometry READ windowGeometry WRITE setWindowGeometry NOTIFY windowGeometryChanged)
    Q_PROPERTY(bool windowMaximized READ windowMaximized WRITE setWindowMaximized NOTIFY windowMaximizedChanged)

public:
    // Map sources: "offline" (built-in base map only), "xyz" (tileUrlTemplate), "mbtiles" (mbtilesFile).
    // `vault` keeps the remembered password; it must outlive this object.
    AppSettings(QSettings *storage, secrets::PasswordVault *vault, QObject *parent = nullptr);

    QString lastServer() const;
    void setLastServer(const QString &server);
    QString lastUser() const;
    void setLastUser(const QString &user);
    // On only while a keyring is reachable and the operator asked for it.
    bool rememberPassword() const;
    void setRememberPassword(bool remember);
    // The password of this session: typed, or read back from the keyring for lastServer/lastUser.
    QString password() const { return m_password; }
    void setPassword(const QString &password);
    bool canRememberPassword() const;
    // What the login view says beside "remember": no keyring (and why), a keyring that refused, a
    // password moved out of the settings file. Empty when there is nothing to say.
    QString passwordNotice() const;
    QString mapSource() const;
    void setMapSource(const QString &source);
    QString tileUrlTemplate() const;
    void setTileUrlTemplate(const QString &urlTemplate);
    QString mbtilesFile() const;
    void setMbtilesFile(const QString &file);
    QString orthophotoFile() const;
    void setOrthophotoFile(const QString &file);
    // 0..1, 0.8 when never chosen.
    double orthophotoOpacity() const;
    void setOrthophotoOpacity(double opacity);
    QString demPath() const;
    void setDemPath(const QString &path);
    QString units() const;
    void setUnits(const QString &units);
    // The UI's language: "" follows the system, else a language code ("en", "de", "es", "uk");
    // Translations applies it, without a restart.
    QString language() const;
    void setLanguage(const QString &language);
    // The colours the window is drawn in, applied at once (ui::MainWindow's Theme follows it).
    QString colourScheme() const;
    void setColourScheme(const QString &scheme);
    QRect windowGeometry() const;
    void setWindowGeometry(const QRect &geometry);
    bool windowMaximized() const;
    void setWindowMaximized(bool maximized);

    // The login the operator is trying: becomes lastServer/lastUser; the password is held in memory.
    Q_INVOKABLE void rememberLogin(const QString &server, const QString &user, const QString &password);
    // The server accepted it: while "remember" is on, the password goes into the keyring for that
    // server and user. A refused password never replaces the one remembered.
    void loginSucceeded();

    // Writes everything to disk now (QSettings otherwise writes lazily).
    Q_INVOKABLE void sync();

signals:
    // One signal a property, so a binding re-evaluates only when its own setting changes.
    void lastServerChanged();
    void lastUserChanged();
    void rememberPasswordChanged();
    void passwordChanged();
    void canRememberPasswordChanged();
    void passwordNoticeChanged();
    void mapSourceChanged();
    void tileUrlTemplateChanged();
    void mbtilesFileChanged();
    void orthophotoFileChanged();
    void orthophotoOpacityChanged();
    void demPathChanged();
    void unitsChanged();
    void languageChanged();
    void colourSchemeChanged();
    void windowGeometryChanged();
    void windowMaximizedChanged();
    // The keyring gave back the remembered password (the login view fills an empty field with it).
    void passwordRecalled();

private:
    // Stores a value; `notify` is emitted when it differs from the one kept.
    void write(const QString &key, const QVariant &value, void (AppSettings::*notify)());
    bool rememberWanted() const;
    void keyringChecked();
    void setNotice(const QString &notice);

    QSettings *m_storage;
    secrets::PasswordVault *m_vault;
    QString m_password;
    // A plain-text password an older version left in the settings, on its way to the keyring: it is
    // out of the file already and kept in memory until the keyring has it (or is known to be absent).
    struct PlainPassword
    {
        QString server;
        QString user;
        QString password;
    };
    std::optional<PlainPassword> m_plain;
    bool m_moving = false; // the plain password's keyring write is under way
    QString m_notice;
};

} // namespace sortie::ui
