#include "GamepadManager.h"

#include "Gamepad.h"
#include "GamepadLog.h"

#include <QCoreApplication>
#include <QHash>

#include <SDL.h>

#include <atomic>
#include <iterator>
#include <optional>

namespace sortie::gamepad {

namespace {

// SDL is process-wide: one manager owns its initialisation at a time.
std::atomic<bool> s_sdlOwned{false};

std::optional<Axis> axisFromSdl(int axis)
{
    switch (axis) {
    case SDL_CONTROLLER_AXIS_LEFTX: return Axis::LeftX;
    case SDL_CONTROLLER_AXIS_LEFTY: return Axis::LeftY;
    case SDL_CONTROLLER_AXIS_RIGHTX: return Axis::RightX;
    case SDL_CONTROLLER_AXIS_RIGHTY: return Axis::RightY;
    case SDL_CONTROLLER_AXIS_TRIGGERLEFT: return Axis::TriggerLeft;
    case SDL_CONTROLLER_AXIS_TRIGGERRIGHT: return Axis::TriggerRight;
    default: return std::nullopt;
    }
}

std::optional<Button> buttonFromSdl(int button)
{
    switch (button) {
    case SDL_CONTROLLER_BUTTON_A: return Button::A;
    case SDL_CONTROLLER_BUTTON_B: return Button::B;
    case SDL_CONTROLLER_BUTTON_X: return Button::X;
    case SDL_CONTROLLER_BUTTON_Y: return Button::Y;
    case SDL_CONTROLLER_BUTTON_BACK: return Button::Back;
    case SDL_CONTROLLER_BUTTON_GUIDE: return Button::Guide;
    case SDL_CONTROLLER_BUTTON_START: return Button::Start;
    case SDL_CONTROLLER_BUTTON_LEFTSTICK: return Button::LeftStick;
    case SDL_CONTROLLER_BUTTON_RIGHTSTICK: return Button::RightStick;
    case SDL_CONTROLLER_BUTTON_LEFTSHOULDER: return Button::LeftShoulder;
    case SDL_CONTROLLER_BUTTON_RIGHTSHOULDER: return Button::RightShoulder;
    case SDL_CONTROLLER_BUTTON_DPAD_UP: return Button::DpadUp;
    case SDL_CONTROLLER_BUTTON_DPAD_DOWN: return Button::DpadDown;
    case SDL_CONTROLLER_BUTTON_DPAD_LEFT: return Button::DpadLeft;
    case SDL_CONTROLLER_BUTTON_DPAD_RIGHT: return Button::DpadRight;
    case SDL_CONTROLLER_BUTTON_MISC1: return Button::Misc;
    case SDL_CONTROLLER_BUTTON_PADDLE1: return Button::Paddle1;
    case SDL_CONTROLLER_BUTTON_PADDLE2: return Button::Paddle2;
    case SDL_CONTROLLER_BUTTON_PADDLE3: return Button::Paddle3;
    case SDL_CONTROLLER_BUTTON_PADDLE4: return Button::Paddle4;
    case SDL_CONTROLLER_BUTTON_TOUCHPAD: return Button::Touchpad;
    default: return std::nullopt;
    }
}

SDL_GameControllerAxis sdlAxis(Axis axis)
{
    switch (axis) {
    case Axis::LeftX: return SDL_CONTROLLER_AXIS_LEFTX;
    case Axis::LeftY: return SDL_CONTROLLER_AXIS_LEFTY;
    case Axis::RightX: return SDL_CONTROLLER_AXIS_RIGHTX;
    case Axis::RightY: return SDL_CONTROLLER_AXIS_RIGHTY;
    case Axis::TriggerLeft: return SDL_CONTROLLER_AXIS_TRIGGERLEFT;
    case Axis::TriggerRight: return SDL_CONTROLLER_AXIS_TRIGGERRIGHT;
    }
    return SDL_CONTROLLER_AXIS_INVALID;
}

QString sdlError()
{
    return QString::fromUtf8(SDL_GetError());
}

} // namespace

// The SDL side of each gamepad, kept out of the header: the open controller by instance id.
struct GamepadManager::Sdl
{
    QHash<int, SDL_GameController *> controllers;
};

GamepadManager::GamepadManager(QObject *parent)
    : QAbstractListModel(parent), m_sdl(std::make_unique<Sdl>())
{
    bool expected = false;
    if (!s_sdlOwned.compare_exchange_strong(expected, true)) {
        m_error = QCoreApplication::translate("sortie::gamepad::GamepadManager",
                                              "Another gamepad manager already owns SDL in this program.");
        qCWarning(lcGamepad) << m_error;
        return;
    }
    // Before SDL_Init: hints read when the subsystems start.
    SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    if (SDL_Init(SDL_INIT_GAMECONTROLLER) != 0) {
        m_error = QCoreApplication::translate("sortie::gamepad::GamepadManager", "Gamepads are not available: %1")
                      .arg(sdlError());
        qCWarning(lcGamepad) << m_error;
        SDL_Quit();
        s_sdlOwned = false;
        return;
    }
    SDL_GameControllerEventState(SDL_ENABLE);
    m_available = true;
    qCInfo(lcGamepad) << "SDL" << sdlVersion() << "started; gamepads checked every" << kIdleCheckMs << "ms";

    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &GamepadManager::poll);
    updateTimer();
    // The devices already plugged in: SDL queued their arrival in SDL_Init; seen at once, not in a second.
    QTimer::singleShot(0, this, &GamepadManager::poll);
}

GamepadManager::~GamepadManager()
{
    m_timer.stop();
    if (!m_available)
        return;
    for (Gamepad *pad : std::as_const(m_pads))
        delete pad;
    m_pads.clear();
    for (SDL_GameController *controller : std::as_const(m_sdl->controllers))
        SDL_GameControllerClose(controller);
    m_sdl->controllers.clear();
    SDL_Quit();
    s_sdlOwned = false;
    qCDebug(lcGamepad) << "SDL stopped";
}

QString GamepadManager::sdlVersion() const
{
    SDL_version version;
    SDL_GetVersion(&version);
    return QStringLiteral("%1.%2.%3").arg(version.major).arg(version.minor).arg(version.patch);
}

Gamepad *GamepadManager::gamepad(int row) const
{
    return row >= 0 && row < m_pads.size() ? m_pads.at(row) : nullptr;
}

int GamepadManager::pollIntervalMs() const
{
    return m_timer.isActive() ? m_timer.interval() : 0;
}

int GamepadManager::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_pads.size());
}

QVariant GamepadManager::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_pads.size())
        return {};
    Gamepad *pad = m_pads.at(index.row());
    switch (role) {
    case Qt::DisplayRole:
    case NameRole: return pad->name();
    case GuidRole: return pad->guid();
    case GamepadRole: return QVariant::fromValue(static_cast<QObject *>(pad));
    default: return {};
    }
}

QHash<int, QByteArray> GamepadManager::roleNames() const
{
    return {{NameRole, "name"}, {GuidRole, "guid"}, {GamepadRole, "gamepad"}};
}

int GamepadManager::rowOf(int instanceId) const
{
    for (int row = 0; row < m_pads.size(); ++row) {
        if (m_pads.at(row)->instanceId() == instanceId)
            return row;
    }
    return -1;
}

void GamepadManager::updateTimer()
{
    if (!m_available)
        return;
    const int interval = m_pads.isEmpty() ? kIdleCheckMs : kActivePollMs;
    if (m_timer.isActive() && m_timer.interval() == interval)
        return;
    qCDebug(lcGamepad) << "pumping SDL's events every" << interval << "ms";
    m_timer.start(interval);
}

void GamepadManager::poll()
{
    if (!m_available)
        return;
    // One pump (SDL_JoystickUpdate: the devices' state and hot-plugging), then every queued event.
    SDL_PumpEvents();
    SDL_Event events[64];
    QList<Gamepad *> moved;
    for (;;) {
        const int n = SDL_PeepEvents(events, int(std::size(events)), SDL_GETEVENT, SDL_FIRSTEVENT, SDL_LASTEVENT);
        if (n <= 0)
            break;
        for (int i = 0; i < n; ++i) {
            const SDL_Event &e = events[i];
            switch (e.type) {
            case SDL_CONTROLLERDEVICEADDED:
                open(e.cdevice.which);  // a device index
                break;
            case SDL_CONTROLLERDEVICEREMOVED:
            case SDL_JOYDEVICEREMOVED:  // the same instance id; whichever comes first closes it
                close(e.type == SDL_JOYDEVICEREMOVED ? e.jdevice.which : e.cdevice.which);
                break;
            case SDL_JOYDEVICEADDED:
                if (!SDL_IsGameController(e.jdevice.which)) {
                    qCInfo(lcGamepad) << "joystick" << SDL_JoystickNameForIndex(e.jdevice.which)
                                      << "has no game-controller mapping: not used";
                }
                break;
            case SDL_CONTROLLERDEVICEREMAPPED:
                qCInfo(lcGamepad) << "gamepad" << e.cdevice.which << "remapped";
                break;
            case SDL_CONTROLLERAXISMOTION: {
                const int row = rowOf(e.caxis.which);
                const auto axis = axisFromSdl(e.caxis.axis);
                if (row >= 0 && axis) {
                    Gamepad *pad = m_pads.at(row);
                    pad->setRawAxis(*axis, e.caxis.value);
                    if (!moved.contains(pad))
                        moved.append(pad);
                }
                break;
            }
            case SDL_CONTROLLERBUTTONDOWN:
            case SDL_CONTROLLERBUTTONUP: {
                const int row = rowOf(e.cbutton.which);
                const auto button = buttonFromSdl(e.cbutton.button);
                if (row >= 0 && button)
                    m_pads.at(row)->setButton(*button, e.cbutton.state == SDL_PRESSED);
                break;
            }
            default:
                break;
            }
        }
    }
    // One axesChanged per gamepad and pump, after every event of the pump.
    for (Gamepad *pad : std::as_const(moved)) {
        if (m_pads.contains(pad))
            pad->flushAxes();
    }
    updateTimer();
}

void GamepadManager::open(int deviceIndex)
{
    const SDL_JoystickID instanceId = SDL_JoystickGetDeviceInstanceID(deviceIndex);
    if (instanceId < 0 || rowOf(instanceId) >= 0)
        return;  // gone again, or already open (SDL may announce a device twice)
    SDL_GameController *controller = SDL_GameControllerOpen(deviceIndex);
    if (!controller) {
        qCWarning(lcGamepad) << "gamepad" << deviceIndex << "could not be opened:" << sdlError();
        return;
    }
    SDL_Joystick *joystick = SDL_GameControllerGetJoystick(controller);
    char guid[33] = {};
    SDL_JoystickGetGUIDString(SDL_JoystickGetGUID(joystick), guid, int(sizeof guid));
    const char *name = SDL_GameControllerName(controller);
    auto *pad = new Gamepad(SDL_JoystickInstanceID(joystick), QString::fromUtf8(name ? name : "Gamepad"),
                            QString::fromLatin1(guid), this);
    // Its state now, before any event: a button held while it was plugged in is no press.
    for (int i = 0; i < kAxisCount; ++i)
        pad->setRawAxis(Axis(i), SDL_GameControllerGetAxis(controller, sdlAxis(Axis(i))));
    for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX; ++b) {
        if (const auto button = buttonFromSdl(b))
            pad->setButton(*button, SDL_GameControllerGetButton(controller, SDL_GameControllerButton(b)) != 0, false);
    }
    pad->flushAxes();
    m_sdl->controllers.insert(pad->instanceId(), controller);
    const int row = int(m_pads.size());
    beginInsertRows({}, row, row);
    m_pads.append(pad);
    endInsertRows();
    qCInfo(lcGamepad) << "gamepad attached:" << pad->name() << pad->guid();
    emit countChanged();
    emit gamepadAdded(pad);
    updateTimer();
}

void GamepadManager::close(int instanceId)
{
    const int row = rowOf(instanceId);
    if (row < 0)
        return;
    Gamepad *pad = m_pads.at(row);
    pad->markDetached();  // axes 0, buttons released, detached()
    beginRemoveRows({}, row, row);
    m_pads.removeAt(row);
    endRemoveRows();
    if (SDL_GameController *controller = m_sdl->controllers.take(instanceId))
        SDL_GameControllerClose(controller);
    emit countChanged();
    emit gamepadRemoved(pad);
    pad->deleteLater();
    updateTimer();
}

} // namespace sortie::gamepad
