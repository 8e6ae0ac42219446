// A gamepad's buttons in the real window, offscreen, against sortie-sim's VCI vehicle, through
// SDL's virtual joysticks (no hardware): the operator switches the gamepad on in the command bar;
// Start asks "Arm …?" as the Arm button does (the checklist and the question first, nothing sent
// by the press alone), and arms once answered; A ("photo", the camera's) asks nothing of the
// command bar. Switched off, SDL is closed and no gamepad is listed.
#include "ClientWindow.h"
#include "Gamepad.h"
#include "GamepadCommands.h"
#include "GamepadManager.h"
#include "QuickScene.h"
#include "VehicleLayer.h"
#include "VirtualPad.h"

#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

class TestGamepadCommands : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_client;

    void click(const char *name)
    {
        QQuickItem *item = m_client->find(QString::fromLatin1(name));
        QVERIFY2(item, name);
        QTRY_VERIFY2(item->isVisible() && item->isEnabled() && item->width() > 0, name);
        QVERIFY(test::waitForFrame(m_client->window()));
        QTest::mouseClick(m_client->window(), Qt::LeftButton, {}, item->mapToScene(QPointF(item->width() / 2, item->height() / 2)).toPoint());
    }
    bool opened(const char *name) const { return m_client->find<QObject>(QString::fromLatin1(name))->property("opened").toBool(); }

private slots:
    void initTestCase() { test::useSoftwareRendering(); }
    void cleanupTestCase() { m_client.reset(); }

    void buttonsAskAsTheCommandBarDoes()
    {
        m_client = std::make_unique<test::ClientWindow>(test::ClientWindow::Options{});
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
        gamepad::GamepadCommands *gamepads = m_client->graph().gamepads();
        QVERIFY(gamepads);
        QVERIFY(!gamepads->isEnabled() && !gamepads->manager()); // off by default: SDL not started
        QVERIFY(m_client->addVciVehicles());
        QTest::keyClick(m_client->window(), Qt::Key_3, Qt::ControlModifier);
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        QTRY_COMPARE_WITH_TIMEOUT(layer->positionedCount(), 1, 10000);
        layer->setCurrentIndex(0);
        vehicle::Vehicle *v = m_client->fleet().vehicleAt(0);

        click("gamepadButton");
        QTRY_VERIFY(gamepads->isEnabled());
        QVERIFY2(gamepads->manager()->isAvailable(), qPrintable(gamepads->manager()->errorString()));
        test::VirtualPad pad;
        QVERIFY(pad.attach("Sortie test pad"));
        QTRY_COMPARE(gamepads->manager()->count(), 1);
        QCOMPARE(gamepads->status(), QStringLiteral("Sortie test pad"));
        QTRY_VERIFY_WITH_TIMEOUT(m_client->fleet().commands()->blockers(client::CommandPolicy::Command::Arm, v).isEmpty(), 10000);

        // A press is seen once SDL's events are pumped (every 16 ms): held until the gamepad says so.
        gamepad::Gamepad *seen = gamepads->manager()->gamepad(0);
        const auto press = [&](int sdlButton, gamepad::GamepadControls::Button button) {
            pad.setButton(sdlButton, true);
            QTRY_VERIFY(seen->button(button));
            pad.setButton(sdlButton, false);
            QTRY_VERIFY(!seen->button(button));
        };
        // A: the camera's photo, not a command of the bar: nothing asks.
        press(SDL_CONTROLLER_BUTTON_A, gamepad::GamepadControls::Button::A);
        QVERIFY(!opened("commandConfirmDialog") && !opened("checklistOverrideDialog"));
        // Start: the question the Arm button asks; the press alone sends nothing.
        press(SDL_CONTROLLER_BUTTON_START, gamepad::GamepadControls::Button::Start);
        QObject *dialog = m_client->find<QObject>(QStringLiteral("commandConfirmDialog"));
        QTRY_VERIFY(dialog->property("opened").toBool());
        QCOMPARE(dialog->property("text").toString(), QStringLiteral("Arm %1? Its motors may start.").arg(v->name()));
        QVERIFY(!v->armed());
        QMetaObject::invokeMethod(dialog, "accept");
        QTRY_VERIFY_WITH_TIMEOUT(v->armed(), 10000);

        // Off: SDL closed, nothing listed, the button follows.
        pad.detach();
        QTRY_COMPARE(gamepads->manager()->count(), 0);
        click("gamepadButton");
        QTRY_VERIFY(!gamepads->isEnabled());
        QVERIFY(!gamepads->manager());
        QVERIFY(!m_client->find<QObject>(QStringLiteral("gamepadButton"))->property("checked").toBool());
        QCOMPARE(gamepads->status(), QStringLiteral("Gamepads off"));
    }
};

QTEST_MAIN(TestGamepadCommands)
#include "tst_gamepadcommands.moc"
