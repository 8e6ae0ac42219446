#pragma once

#include "Gamepad.h"

#include <QAbstractListModel>
#include <QList>
#include <QString>
#include <QTimer>

#include <memory>

namespace sortie::gamepad {

// SDL's one initialisation and the list of attached gamepads (docs/gamepad.md). The constructor
// sets SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS (a window in the background still hears its
// gamepad) and SDL_HINT_NO_SIGNAL_HANDLERS (SDL takes no SIGINT or SIGTERM from the program) and
// calls SDL_Init(SDL_INIT_GAMECONTROLLER): joysticks and events, no video, so it needs no display;
// the destructor calls SDL_Quit. One manager lives at a time: a second one while the first lives
// is not available (errorString says why) and leaves SDL alone.
//
// SDL's events are pumped from a QTimer in this object's thread: every kActivePollMs (16 ms) while a
// gamepad is attached, else every kIdleCheckMs (1 s) to see new devices, so an idle client does not
// wake 60 times a second for nothing (pollIntervalMs() tells which; tst_gamepad checks both).
//
// A list model of the attached gamepads (roles name, guid, gamepad), in the order they came. A
// device SDL has a game-controller mapping for becomes a Gamepad (gamepadAdded); a joystick without
// one is logged and left alone. When SDL reports one gone, its Gamepad is marked detached (its
// axes read 0, its held buttons released: Gamepad::markDetached), its row goes and gamepadRemoved
// is emitted with it; it is deleted later (deleteLater).
class GamepadManager : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY countChanged FINAL)
    Q_PROPERTY(bool available READ isAvailable CONSTANT FINAL)
    Q_PROPERTY(QString errorString READ errorString CONSTANT FINAL)

public:
    enum Role { NameRole = Qt::UserRole + 1, GuidRole, GamepadRole };
    Q_ENUM(Role)

    static constexpr int kActivePollMs = 16;
    static constexpr int kIdleCheckMs = 1000;

    explicit GamepadManager(QObject *parent = nullptr);
    ~GamepadManager() override;

    bool isAvailable() const { return m_available; }
    QString errorString() const { return m_error; }
    // "SDL 2.26.5" (the library loaded, not the one compiled against).
    QString sdlVersion() const;

    int count() const { return int(m_pads.size()); }
    Q_INVOKABLE sortie::gamepad::Gamepad *gamepad(int row) const;
    QList<Gamepad *> gamepads() const { return m_pads; }

    // The timer's interval now: kActivePollMs with a gamepad attached, kIdleCheckMs without; 0
    // when SDL is not available (no timer).
    int pollIntervalMs() const;

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

signals:
    void gamepadAdded(sortie::gamepad::Gamepad *gamepad);
    // Emitted after the gamepad's axes read 0 (Gamepad::detached); the object lives until the event
    // loop deletes it.
    void gamepadRemoved(sortie::gamepad::Gamepad *gamepad);
    void countChanged();

private:
    struct Sdl;

    void poll();
    void open(int deviceIndex);
    void close(int instanceId);
    void updateTimer();
    int rowOf(int instanceId) const;

    bool m_available = false;
    QString m_error;
    std::unique_ptr<Sdl> m_sdl;
    QList<Gamepad *> m_pads;
    QTimer m_timer;
};

} // namespace sortie::gamepad
