#pragma once

#include "CommandPolicy.h"

#include <QObject>
#include <QPointer>

#include <map>
#include <memory>
#include <optional>

class QSettings;

namespace sortie::gamepad {

class Gamepad;
class GamepadManager;
class GamepadSettings;

// The gamepads' buttons as the command bar's commands. A button whose action (GamepadSettings,
// kept per gamepad under "gamepads/") names a command — "arm", "disarm", "takeoff", "auto",
// "hold", "land", "returnHome" — asks for it (commandRequested), and the command bar gives it as
// if its own button were clicked: through the pre-flight checklist and the confirmation, so a
// press never arms a vehicle by itself. Other actions ("photo", "record") are the camera's.
//
// SDL is started only while the operator has the gamepads enabled (the setting gamepad/enabled,
// off by default): a client that uses none never initialises SDL or polls for devices.
class GamepadCommands : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool enabled READ isEnabled WRITE setEnabled NOTIFY enabledChanged FINAL)
    // "No gamepad", the attached gamepads' names, or why SDL could not start.
    Q_PROPERTY(QString status READ status NOTIFY statusChanged FINAL)

public:
    // `storage` (not owned, required) keeps the setting and each gamepad's settings.
    explicit GamepadCommands(QSettings *storage, QObject *parent = nullptr);
    ~GamepadCommands() override;

    bool isEnabled() const { return m_manager != nullptr; }
    void setEnabled(bool enabled);
    QString status() const;
    GamepadManager *manager() const { return m_manager.get(); } // nullptr while disabled

    // The command an action names; nullopt for one that is not a command.
    static std::optional<client::CommandPolicy::Command> commandFor(const QString &action);

signals:
    void commandRequested(sortie::client::CommandPolicy::Command command);
    void enabledChanged();
    void statusChanged();

private:
    void start();
    void attach(Gamepad *pad);

    QSettings *m_storage;
    std::unique_ptr<GamepadManager> m_manager;
    std::map<Gamepad *, std::unique_ptr<GamepadSettings>> m_settings;
};

} // namespace sortie::gamepad
