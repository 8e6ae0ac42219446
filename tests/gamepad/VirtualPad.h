#pragma once
// One virtual game controller of SDL's (SDL_JoystickAttachVirtualEx), for the gamepad tests: no
// hardware, no display.
#include <QTest>
#include <QByteArray>
#include <QDebug>

#include <SDL.h>

namespace sortie::test {

// A trigger of the virtual game controller maps SDL's whole raw range onto 0..32767: released is
// -32768 on the virtual joystick.
constexpr Sint16 kTriggerReleased = -32768;

// One virtual game controller: every SDL_GameController axis and button, in SDL's order, so that
// virtual axis i is SDL_GameControllerAxis i and virtual button i SDL_GameControllerButton i.
class VirtualPad
{
public:
    VirtualPad() = default;
    VirtualPad(const VirtualPad &) = delete;
    VirtualPad &operator=(const VirtualPad &) = delete;
    ~VirtualPad() { detach(); }

    bool attach(const char *name)
    {
        SDL_VirtualJoystickDesc desc;
        SDL_zero(desc);
        desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
        desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
        desc.naxes = SDL_CONTROLLER_AXIS_MAX;
        desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
        desc.axis_mask = (1u << SDL_CONTROLLER_AXIS_MAX) - 1;
        desc.button_mask = (1u << SDL_CONTROLLER_BUTTON_MAX) - 1;
        desc.vendor_id = 0x1209;  // pid.codes' test range
        desc.product_id = 0x0001;
        desc.name = name;
        const int index = SDL_JoystickAttachVirtualEx(&desc);
        if (index < 0) {
            qWarning() << "SDL_JoystickAttachVirtualEx:" << SDL_GetError();
            return false;
        }
        if (!SDL_IsGameController(index)) {
            // Not taken with Debian 12's SDL 2.26.5: it makes a virtual game controller's mapping
            // itself from the description's masks (VIRTUAL_JoystickGetGamepadMapping; SDL before
            // 2.24 had no such description and returned none). Kept for an SDL that gives none:
            // a mapping from the device's GUID, every button and axis in SDL's order, the triggers
            // as full-range axes as SDL's own mapping has them. The test logs when it adds one.
            char guid[33] = {};
            SDL_JoystickGetGUIDString(SDL_JoystickGetDeviceGUID(index), guid, int(sizeof guid));
            const QByteArray mapping = QByteArray(guid) + ',' + name
                + ",a:b0,b:b1,x:b2,y:b3,back:b4,guide:b5,start:b6,leftstick:b7,rightstick:b8,leftshoulder:b9,"
                  "rightshoulder:b10,dpup:b11,dpdown:b12,dpleft:b13,dpright:b14,misc1:b15,paddle1:b16,paddle2:b17,"
                  "paddle3:b18,paddle4:b19,touchpad:b20,leftx:a0,lefty:a1,rightx:a2,righty:a3,lefttrigger:a4,"
                  "righttrigger:a5,";
            qInfo() << "SDL gave the virtual joystick no game-controller mapping: adding" << mapping;
            if (SDL_GameControllerAddMapping(mapping.constData()) < 0 || !SDL_IsGameController(index)) {
                qWarning() << "SDL_GameControllerAddMapping:" << SDL_GetError();
                return false;
            }
        }
        m_joystick = SDL_JoystickOpen(index);
        if (!m_joystick) {
            qWarning() << "SDL_JoystickOpen:" << SDL_GetError();
            return false;
        }
        m_instanceId = SDL_JoystickInstanceID(m_joystick);
        setAxis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, kTriggerReleased);
        setAxis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, kTriggerReleased);
        return true;
    }

    void setAxis(int axis, Sint16 value) { QVERIFY(SDL_JoystickSetVirtualAxis(m_joystick, axis, value) == 0); }
    void setButton(int button, bool down)
    {
        QVERIFY(SDL_JoystickSetVirtualButton(m_joystick, button, down ? SDL_PRESSED : SDL_RELEASED) == 0);
    }

    void detach()
    {
        if (!m_joystick)
            return;
        SDL_JoystickClose(m_joystick);  // the test's own handle; the manager's controller stays open
        m_joystick = nullptr;
        for (int i = 0; i < SDL_NumJoysticks(); ++i) {
            if (SDL_JoystickGetDeviceInstanceID(i) == m_instanceId) {
                SDL_JoystickDetachVirtual(i);
                break;
            }
        }
    }

    int instanceId() const { return m_instanceId; }

private:
    SDL_Joystick *m_joystick = nullptr;
    SDL_JoystickID m_instanceId = -1;
};

} // namespace sortie::test
