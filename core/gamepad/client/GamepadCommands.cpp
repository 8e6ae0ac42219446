#include "GamepadCommands.h"

#include "Gamepad.h"
#include "GamepadLog.h"
#include "GamepadManager.h"
#include "GamepadSettings.h"

#include <QSettings>

namespace sortie::gamepad {

using client::CommandPolicy;

namespace {
const QString kEnabledKey = QStringLiteral("gamepad/enabled");
const QString kSettingsGroup = QStringLiteral("gamepads");
} // namespace

GamepadCommands::GamepadCommands(QSettings *storage, QObject *parent)
    : QObject(parent)
    , m_storage(storage)
{
    Q_ASSERT(storage);
    if (m_storage->value(kEnabledKey, false).toBool())
        start();
}

GamepadCommands::~GamepadCommands()
{
    m_settings.clear();
    m_manager.reset();
}

void GamepadCommands::setEnabled(bool enabled)
{
    if (enabled == isEnabled())
        return;
    m_storage->setValue(kEnabledKey, enabled);
    if (enabled) {
        start();
    } else {
        m_settings.clear();
        m_manager.reset(); // SDL_Quit: nothing polls any more
        qCInfo(lcGamepad) << "gamepads off";
    }
    emit enabledChanged();
    emit statusChanged();
}

void GamepadCommands::start()
{
    m_manager = std::make_unique<GamepadManager>();
    if (!m_manager->isAvailable())
        qCWarning(lcGamepad).noquote() << "gamepads unavailable:" << m_manager->errorString();
    connect(m_manager.get(), &GamepadManager::gamepadAdded, this, &GamepadCommands::attach);
    connect(m_manager.get(), &GamepadManager::gamepadRemoved, this, [this](Gamepad *pad) {
        m_settings.erase(pad);
        emit statusChanged();
    });
    for (Gamepad *pad : m_manager->gamepads())
        attach(pad);
}

void GamepadCommands::attach(Gamepad *pad)
{
    auto settings = std::make_unique<GamepadSettings>(m_storage, kSettingsGroup, pad->guid());
    settings->bind(pad);
    GamepadSettings *mapping = settings.get();
    m_settings[pad] = std::move(settings);
    connect(pad, &Gamepad::buttonPressed, this, [this, mapping](GamepadControls::Button button) {
        const QString action = mapping->action(button);
        if (const auto command = commandFor(action)) {
            qCInfo(lcGamepad).noquote() << "button" << buttonName(button) << "asks for" << action;
            emit commandRequested(*command);
        }
    });
    emit statusChanged();
}

QString GamepadCommands::status() const
{
    if (!m_manager)
        return tr("Gamepads off");
    if (!m_manager->isAvailable())
        return tr("Gamepads unavailable: %1").arg(m_manager->errorString());
    QStringList names;
    for (const Gamepad *pad : m_manager->gamepads())
        names << pad->name();
    return names.isEmpty() ? tr("No gamepad attached") : names.join(QStringLiteral(", "));
}

std::optional<CommandPolicy::Command> GamepadCommands::commandFor(const QString &action)
{
    static const std::pair<const char *, CommandPolicy::Command> kCommands[] = {
        {"arm", CommandPolicy::Command::Arm},   {"disarm", CommandPolicy::Command::Disarm},
        {"takeoff", CommandPolicy::Command::TakeOff}, {"auto", CommandPolicy::Command::Auto},
        {"hold", CommandPolicy::Command::Hold}, {"land", CommandPolicy::Command::Land},
        {"returnHome", CommandPolicy::Command::ReturnHome}};
    for (const auto &[name, command] : kCommands)
        if (action == QLatin1String(name))
            return command;
    return std::nullopt;
}

} // namespace sortie::gamepad
