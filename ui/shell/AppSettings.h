#pragma once

#include <QObject>
#include <QRect>
#include <QtQml/qqmlregistration.h>

class QSettings;

namespace sortie::ui {

// What the operator chose last time, kept in QSettings: server, user, window geometry, map
// source and units. The password is held in memory for the session and written only while
// `rememberPassword` is on; turning it off erases the stored copy. Nothing here is logged.
class AppSettings : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("AppSettings is created by the application")
    Q_PROPERTY(QString lastServer READ lastServer WRITE setLastServer NOTIFY changed)
    Q_PROPERTY(QString lastUser READ lastUser WRITE setLastUser NOTIFY changed)
    Q_PROPERTY(bool rememberPassword READ rememberPassword WRITE setRememberPassword NOTIFY changed)
    Q_PROPERTY(QString password READ password WRITE setPassword NOTIFY changed)
    Q_PROPERTY(QString mapSource READ mapSource WRITE setMapSource NOTIFY changed)
    Q_PROPERTY(QString tileUrlTemplate READ tileUrlTemplate WRITE setTileUrlTemplate NOTIFY changed)
    Q_PROPERTY(QString mbtilesFile READ mbtilesFile WRITE setMbtilesFile NOTIFY changed)
    Q_PROPERTY(QString units READ units WRITE setUnits NOTIFY changed)
    Q_PROPERTY(QRect windowGeometry READ windowGeometry WRITE setWindowGeometry NOTIFY changed)
    Q_PROPERTY(bool windowMaximized READ windowMaximized WRITE setWindowMaximized NOTIFY changed)

public:
    // Map sources: "offline" (built-in base map only), "xyz" (tileUrlTemplate), "mbtiles" (mbtilesFile).
    explicit AppSettings(QSettings *storage, QObject *parent = nullptr);

    QString lastServer() const;
    void setLastServer(const QString &server);
    QString lastUser() const;
    void setLastUser(const QString &user);
    bool rememberPassword() const;
    void setRememberPassword(bool remember);
    QString password() const { return m_password; }
    void setPassword(const QString &password);
    QString mapSource() const;
    void setMapSource(const QString &source);
    QString tileUrlTemplate() const;
    void setTileUrlTemplate(const QString &urlTemplate);
    QString mbtilesFile() const;
    void setMbtilesFile(const QString &file);
    QString units() const;
    void setUnits(const QString &units);
    QRect windowGeometry() const;
    void setWindowGeometry(const QRect &geometry);
    bool windowMaximized() const;
    void setWindowMaximized(bool maximized);

    // Writes everything to disk now (QSettings otherwise writes lazily).
    Q_INVOKABLE void sync();

signals:
    void changed();

private:
    void write(const QString &key, const QVariant &value);

    QSettings *m_storage;
    QString m_password;
};

} // namespace sortie::ui
