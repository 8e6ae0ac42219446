// Gamepads end to end through SDL's virtual joysticks (core/gamepad, docs/gamepad.md): no hardware
// and no display. The test attaches a virtual game controller with SDL's own calls
// (SDL_JoystickAttachVirtualEx), moves its sticks and presses its buttons
// (SDL_JoystickSetVirtualAxis/Button) and detaches it (SDL_JoystickDetachVirtual); what it checks
// is what GamepadManager, Gamepad and GamepadSettings make of that: the list, the shaped axes, the
// buttons' signals, the sticks centred when the gamepad disappears, the events pumped once a second
// when nothing is attached, the settings kept per GUID and the calibration.
#include "Gamepad.h"
#include "GamepadManager.h"
#include "GamepadSettings.h"
#include "StickShaping.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <SDL.h>

#include <memory>

using namespace sortie::gamepad;

#include "VirtualPad.h"

using sortie::test::VirtualPad;
using sortie::test::kTriggerReleased;

class TestGamepad : public QObject
{
    Q_OBJECT

private:
    std::unique_ptr<GamepadManager> m_manager;
    std::unique_ptr<VirtualPad> m_pad;

    // The manager sees the virtual pad within its once-a-second check.
    Gamepad *attachPad(const char *name = "Sortie test pad")
    {
        m_pad = std::make_unique<VirtualPad>();
        if (!m_pad->attach(name))
            return nullptr;
        QElapsedTimer waited;
        waited.start();
        while (m_manager->count() == 0 && waited.elapsed() < 3000)
            QTest::qWait(10);
        for (Gamepad *pad : m_manager->gamepads()) {
            if (pad->instanceId() != m_pad->instanceId())
                continue;
            // SDL reads the virtual device's state at the pump after it was opened: until then its
            // triggers read half pulled (0 on a full-range axis). At rest when both read released.
            waited.restart();
            while ((pad->rawAxis(Axis::TriggerLeft) != 0 || pad->rawAxis(Axis::TriggerRight) != 0) && waited.elapsed() < 1000)
                QTest::qWait(5);
            return pad;
        }
        return nullptr;
    }

private slots:
    void init()
    {
        m_manager = std::make_unique<GamepadManager>();
        QVERIFY2(m_manager->isAvailable(), qPrintable(m_manager->errorString()));
        QTest::qWait(20);  // the first pump
        // The test counts its own virtual gamepads: a real one attached makes it unable to run, and
        // it says so rather than passing for nothing.
        QVERIFY2(m_manager->count() == 0, "a real gamepad is attached to this machine: unplug it, the test counts its virtual ones");
    }

    void cleanup()
    {
        m_pad.reset();
        m_manager.reset();
    }

    void idleClientChecksOncePerSecond()
    {
        QCOMPARE(m_manager->rowCount(), 0);
        QCOMPARE(m_manager->pollIntervalMs(), GamepadManager::kIdleCheckMs);
        qInfo() << "SDL" << m_manager->sdlVersion();
    }

    void listsTheAttachedGamepad()
    {
        QSignalSpy added(m_manager.get(), &GamepadManager::gamepadAdded);
        QElapsedTimer took;
        took.start();
        Gamepad *pad = attachPad();
        QVERIFY(pad);
        // Seen by the once-a-second check, not at once and not after many seconds.
        QVERIFY2(took.elapsed() <= 2000, qPrintable(QString::number(took.elapsed())));
        QCOMPARE(added.count(), 1);
        QCOMPARE(added.at(0).at(0).value<Gamepad *>(), pad);
        QCOMPARE(m_manager->rowCount(), 1);
        const QModelIndex row = m_manager->index(0);
        QCOMPARE(row.data(GamepadManager::NameRole).toString(), QStringLiteral("Sortie test pad"));
        const QString guid = row.data(GamepadManager::GuidRole).toString();
        QCOMPARE(guid.size(), 32);
        QVERIFY(QByteArray::fromHex(guid.toLatin1()).size() == 16);
        QCOMPARE(guid, pad->guid());
        QCOMPARE(m_manager->roleNames().value(GamepadManager::GuidRole), QByteArray("guid"));
        QCOMPARE(row.data(GamepadManager::GamepadRole).value<QObject *>(), static_cast<QObject *>(pad));
        QVERIFY(pad->isAttached());
        // A gamepad attached: its events pumped at 60 Hz.
        QCOMPARE(m_manager->pollIntervalMs(), GamepadManager::kActivePollMs);
        // At rest.
        QCOMPARE(pad->axis(Axis::LeftX), 0.0);
        QCOMPARE(pad->axis(Axis::TriggerLeft), 0.0);
        QCOMPARE(pad->axis(Axis::TriggerRight), 0.0);
    }

    void axisReadsBackShaped()
    {
        Gamepad *pad = attachPad();
        QVERIFY(pad);
        pad->setShaping(Axis::LeftX, AxisShaping{{-20000, 0, 20000}, 0.2, 0.5});
        QSignalSpy axes(pad, &Gamepad::axesChanged);
        m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTX, 12000);
        QTRY_COMPARE(pad->rawAxis(Axis::LeftX), 12000);
        QVERIFY(axes.count() >= 1);
        QCOMPARE(pad->axis(Axis::LeftX), 0.3125);  // 0.6 -> dead zone 0.5 -> expo 0.3125
        m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTX, -12000);
        // QTRY_COMPARE waits on ==, not on QCOMPARE's fuzzy comparison: wait on the raw value.
        QTRY_COMPARE(pad->rawAxis(Axis::LeftX), -12000);
        QCOMPARE(pad->axis(Axis::LeftX), -0.3125);
        // Default shaping elsewhere: the whole range.
        m_pad->setAxis(SDL_CONTROLLER_AXIS_RIGHTY, -32768);
        QTRY_COMPARE(pad->axis(Axis::RightY), -1.0);
        QCOMPARE(pad->axis(Axis::LeftY), 0.0);
        // A trigger pulled all the way.
        m_pad->setAxis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 32767);
        QTRY_COMPARE(pad->axis(Axis::TriggerRight), 1.0);
        QCOMPARE(pad->axis(Axis::TriggerLeft), 0.0);
    }

    void buttonPressReachesItsSignal()
    {
        Gamepad *pad = attachPad();
        QVERIFY(pad);
        QSignalSpy pressed(pad, &Gamepad::buttonPressed);
        QSignalSpy released(pad, &Gamepad::buttonReleased);
        m_pad->setButton(SDL_CONTROLLER_BUTTON_A, true);
        QTRY_COMPARE(pressed.count(), 1);
        QCOMPARE(pressed.at(0).at(0).value<Button>(), Button::A);
        QVERIFY(pad->button(Button::A));
        QVERIFY(!pad->button(Button::B));
        QCOMPARE(released.count(), 0);
        m_pad->setButton(SDL_CONTROLLER_BUTTON_A, false);
        m_pad->setButton(SDL_CONTROLLER_BUTTON_DPAD_UP, true);
        QTRY_COMPARE(released.count(), 1);
        QCOMPARE(released.at(0).at(0).value<Button>(), Button::A);
        QTRY_COMPARE(pressed.count(), 2);
        QCOMPARE(pressed.at(1).at(0).value<Button>(), Button::DpadUp);
        QVERIFY(!pad->button(Button::A));
    }

    // The rule "sticks centred when the gamepad disappears". SDL itself recentres a removed
    // joystick (axes to rest, buttons up) before it reports it gone, so what a listener reads here
    // is the whole chain; that a Gamepad reads 0 whatever its last raw value once detached is
    // tst_stickshaping's gamepadShapesAndCentresWhenDetached.
    void detachingCentresTheSticks()
    {
        Gamepad *pad = attachPad();
        QVERIFY(pad);
        QPointer<Gamepad> held(pad);
        m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTY, -32768);
        m_pad->setAxis(SDL_CONTROLLER_AXIS_RIGHTX, 32767);
        m_pad->setButton(SDL_CONTROLLER_BUTTON_START, true);
        QTRY_COMPARE(pad->axis(Axis::LeftY), -1.0);
        QTRY_COMPARE(pad->axis(Axis::RightX), 1.0);
        QTRY_VERIFY(pad->button(Button::Start));

        QSignalSpy detached(pad, &Gamepad::detached);
        QSignalSpy released(pad, &Gamepad::buttonReleased);
        QSignalSpy removed(m_manager.get(), &GamepadManager::gamepadRemoved);
        QSignalSpy countChanged(m_manager.get(), &GamepadManager::countChanged);
        // What a listener reads when it hears the gamepad go.
        double leftYHeard = 9, rightXHeard = 9;
        bool attachedHeard = true;
        const auto listener = connect(m_manager.get(), &GamepadManager::gamepadRemoved, this, [&](Gamepad *gone) {
            leftYHeard = gone->axis(Axis::LeftY);
            rightXHeard = gone->axis(Axis::RightX);
            attachedHeard = gone->isAttached();
        });
        m_pad->detach();
        QTRY_COMPARE(removed.count(), 1);
        disconnect(listener);
        QCOMPARE(removed.at(0).at(0).value<Gamepad *>(), pad);
        QCOMPARE(detached.count(), 1);
        QCOMPARE(leftYHeard, 0.0);
        QCOMPARE(rightXHeard, 0.0);
        QVERIFY(!attachedHeard);
        QCOMPARE(released.count(), 1);
        QCOMPARE(released.at(0).at(0).value<Button>(), Button::Start);
        QCOMPARE(m_manager->rowCount(), 0);
        QCOMPARE(countChanged.count(), 1);
        // Nothing attached: back to the once-a-second check.
        QCOMPARE(m_manager->pollIntervalMs(), GamepadManager::kIdleCheckMs);
        // Deleted by the event loop, not under the listener's feet.
        QTRY_VERIFY(held.isNull());
    }

    void settingsKeptPerGuid()
    {
        Gamepad *pad = attachPad();
        QVERIFY(pad);
        const QString guid = pad->guid();
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString file = dir.filePath(QStringLiteral("sortie.ini"));
        {
            QSettings storage(file, QSettings::IniFormat);
            GamepadSettings settings(&storage, QStringLiteral("gamepads"), guid);
            // Nothing saved: the defaults.
            QCOMPARE(settings.shaping(Axis::LeftX), GamepadSettings::defaultShaping(Axis::LeftX));
            QCOMPARE(settings.deadZone(Axis::LeftX), 0.05);
            QCOMPARE(settings.calibration(Axis::TriggerLeft), kTriggerCalibration);
            QCOMPARE(settings.action(Button::Start), QStringLiteral("arm"));
            QCOMPARE(settings.action(Button::A), QStringLiteral("photo"));
            QCOMPARE(settings.action(Button::DpadUp), QString());

            QSignalSpy changed(&settings, &GamepadSettings::changed);
            settings.setDeadZone(Axis::LeftX, 0.15);
            settings.setDeadZone(Axis::LeftY, 0.9);  // held to 0.5
            settings.setExpo(Axis::RightY, 0.3);
            settings.setCalibration(Axis::RightX, {-30000, 200, 31000});
            settings.setCalibration(Axis::LeftY, {100, 50, 20});  // not min <= centre < max: refused
            settings.setAction(Button::A, QStringLiteral("returnHome"));
            settings.setAction(Button::Start, QString());  // no action, kept as such
            settings.setAction(Button::DpadUp, QStringLiteral("photo"));
            QCOMPARE(changed.count(), 7);
            QCOMPARE(settings.buttonsFor(QStringLiteral("returnHome")), (QList<Button>{Button::A, Button::B}));

            // Bound to the gamepad: its axes read with them.
            settings.bind(pad);
            QCOMPARE(pad->shaping(Axis::LeftX).deadZone, 0.15);
            settings.setExpo(Axis::LeftX, 1.0);
            QCOMPARE(pad->shaping(Axis::LeftX).expo, 1.0);
            m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTX, 32767);
            QTRY_COMPARE(pad->axis(Axis::LeftX), 1.0);
        }
        // Another program's run: a new QSettings on the same file.
        QSettings storage(file, QSettings::IniFormat);
        QVERIFY(storage.childGroups().contains(QStringLiteral("gamepads")));
        storage.beginGroup(QStringLiteral("gamepads"));
        QCOMPARE(storage.childGroups(), QStringList{guid});
        storage.endGroup();
        GamepadSettings again(&storage, QStringLiteral("gamepads"), guid);
        QCOMPARE(again.deadZone(Axis::LeftX), 0.15);
        QCOMPARE(again.expo(Axis::LeftX), 1.0);
        QCOMPARE(again.deadZone(Axis::LeftY), 0.5);
        QCOMPARE(again.expo(Axis::RightY), 0.3);
        QCOMPARE(again.calibration(Axis::RightX), (AxisCalibration{-30000, 200, 31000}));
        QCOMPARE(again.calibration(Axis::LeftY), AxisCalibration{});
        QCOMPARE(again.action(Button::A), QStringLiteral("returnHome"));
        QCOMPARE(again.action(Button::Start), QString());
        QCOMPARE(again.action(Button::DpadUp), QStringLiteral("photo"));
        QCOMPARE(again.action(Button::B), QStringLiteral("returnHome"));  // never set: the default
        // Another gamepad model's GUID: the defaults.
        GamepadSettings other(&storage, QStringLiteral("gamepads"), QStringLiteral("0300000000000000000000000000ffff"));
        QCOMPARE(other.deadZone(Axis::LeftX), 0.05);
        QCOMPARE(other.action(Button::Start), QStringLiteral("arm"));
        // Reset: the defaults for this one too, in the file as well.
        again.resetToDefaults();
        QCOMPARE(again.deadZone(Axis::LeftX), 0.05);
        QCOMPARE(again.action(Button::Start), QStringLiteral("arm"));
        storage.sync();
        QSettings after(file, QSettings::IniFormat);
        QVERIFY(!after.childGroups().contains(QStringLiteral("gamepads")));
    }

    void calibrationMeasuresTheSticks()
    {
        Gamepad *pad = attachPad();
        QVERIFY(pad);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QSettings storage(dir.filePath(QStringLiteral("sortie.ini")), QSettings::IniFormat);
        GamepadSettings settings(&storage, QStringLiteral("gamepads"), pad->guid());
        settings.bind(pad);
        // This stick rests off the middle.
        m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTX, 300);
        QTRY_COMPARE(pad->rawAxis(Axis::LeftX), 300);

        QSignalSpy calibrating(&settings, &GamepadSettings::calibratingChanged);
        settings.beginCalibration(pad);
        QVERIFY(settings.isCalibrating());
        const auto moveTo = [&](int sdlAxis, Axis axis, Sint16 raw, int read) {
            m_pad->setAxis(sdlAxis, raw);
            QTRY_COMPARE(pad->rawAxis(axis), read);
        };
        moveTo(SDL_CONTROLLER_AXIS_LEFTX, Axis::LeftX, -31000, -31000);
        moveTo(SDL_CONTROLLER_AXIS_LEFTX, Axis::LeftX, 32000, 32000);
        moveTo(SDL_CONTROLLER_AXIS_LEFTX, Axis::LeftX, 300, 300);
        moveTo(SDL_CONTROLLER_AXIS_TRIGGERLEFT, Axis::TriggerLeft, 32767, 32767);
        moveTo(SDL_CONTROLLER_AXIS_TRIGGERLEFT, Axis::TriggerLeft, kTriggerReleased, 0);
        // The right stick only a little one way: not calibrated.
        moveTo(SDL_CONTROLLER_AXIS_RIGHTX, Axis::RightX, 4000, 4000);
        moveTo(SDL_CONTROLLER_AXIS_RIGHTX, Axis::RightX, 0, 0);
        const QList<Axis> calibrated = settings.finishCalibration();
        QVERIFY(!settings.isCalibrating());
        QCOMPARE(calibrated, (QList<Axis>{Axis::LeftX, Axis::TriggerLeft}));
        QCOMPARE(calibrating.count(), 2);
        QCOMPARE(settings.calibration(Axis::LeftX), (AxisCalibration{-31000, 300, 32000}));
        QCOMPARE(settings.calibration(Axis::TriggerLeft), (AxisCalibration{0, 0, 32767}));
        QCOMPARE(settings.calibration(Axis::RightX), AxisCalibration{});
        // Stored in the settings.
        QCOMPARE(storage.value(QStringLiteral("gamepads/%1/axes/LeftX/centre").arg(pad->guid())).toInt(), 300);
        // Read through it: the off-centre rest is 0, the measured ends ±1.
        QCOMPARE(pad->axis(Axis::LeftX), 0.0);
        moveTo(SDL_CONTROLLER_AXIS_LEFTX, Axis::LeftX, 32000, 32000);
        QCOMPARE(pad->axis(Axis::LeftX), 1.0);
        moveTo(SDL_CONTROLLER_AXIS_LEFTX, Axis::LeftX, -31000, -31000);
        QCOMPARE(pad->axis(Axis::LeftX), -1.0);

        // A gamepad gone mid-calibration ends it and stores nothing.
        settings.beginCalibration(pad);
        QVERIFY(settings.isCalibrating());
        m_pad->detach();
        QTRY_VERIFY(!settings.isCalibrating());
        QCOMPARE(settings.finishCalibration(), QList<Axis>{});
    }

    void oneManagerAtATime()
    {
        GamepadManager second;
        QVERIFY(!second.isAvailable());
        QVERIFY(!second.errorString().isEmpty());
        QCOMPARE(second.pollIntervalMs(), 0);
        QVERIFY(m_manager->isAvailable());
        QCOMPARE(m_manager->pollIntervalMs(), GamepadManager::kIdleCheckMs);
    }
};

QTEST_GUILESS_MAIN(TestGamepad)
#include "tst_gamepad.moc"
