// The pre-flight checklist in the real window, offscreen, against a simulated VCI vehicle over a
// real socket, with a checklist file of the operator's: Arm is refused (the dialog says why, the
// vehicle is not asked) until the item to tick is ticked in the checklist popup; then it goes
// through the ordinary confirmation and the vehicle arms. Auto is held back while Sortie has given
// the vehicle no route; sent anyway, the override and its reason are in the command log and in
// the flight log. A checklist file with a mistake is not used, and the panel says where it is.
#include "ClientWindow.h"
#include "FlightLog.h"
#include "FlightRecorder.h"
#include "PreflightChecklists.h"
#include "QuickScene.h"
#include "VehicleChecklist.h"
#include "VehicleLayer.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {
const char kChecklist[] = R"({
  "name": "Field list",
  "items": [
    {"check": "link"},
    {"check": "gps_fix", "minimum": 3},
    {"check": "home"},
    {"title": "Propellers fitted and tight"},
    {"check": "route_on_board", "gates": ["auto"]}
  ]
})";
}

class TestChecklistFlow : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_client;
    QTemporaryDir m_checklists;

    QPoint centreOf(QQuickItem *item) const { return item->mapToScene(QPointF(item->width() / 2, item->height() / 2)).toPoint(); }
    // By the item tree too: a list's delegates have no QObject parent to be found by.
    QQuickItem *item(const QString &name) const
    {
        QQuickItem *found = m_client->find(name);
        return found ? found : test::findItem(m_client->window()->contentItem(), name);
    }
    void click(const QString &name)
    {
        QQuickItem *target = nullptr;
        QTRY_VERIFY2((target = item(name)), qPrintable(name));
        QTRY_VERIFY2(target->isVisible() && target->isEnabled() && target->width() > 0, qPrintable(name));
        QVERIFY(test::waitForFrame(m_client->window())); // laid out where it is drawn
        QTest::mouseClick(m_client->window(), Qt::LeftButton, {}, centreOf(target));
    }
    bool opened(const char *name) const { return m_client->find<QObject>(QString::fromLatin1(name))->property("opened").toBool(); }
    QString text(const char *name) const { return m_client->find<QObject>(QString::fromLatin1(name))->property("text").toString(); }
    int logged(const QString &command) const
    {
        const vehicle::CommandLog &log = *m_client->fleet().commandLog();
        int n = 0;
        for (int i = 0; i < log.count(); ++i)
            n += log.at(i).command == command ? 1 : 0;
        return n;
    }

    void start()
    {
        test::ClientWindow::Options options;
        options.checklistDirectory = m_checklists.path();
        m_client = std::make_unique<test::ClientWindow>(options);
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
        QVERIFY(m_client->addVciVehicles());
        QTest::keyClick(m_client->window(), Qt::Key_3, Qt::ControlModifier); // the fly page
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        QTRY_COMPARE_WITH_TIMEOUT(layer->positionedCount(), 1, 10000);
        layer->setCurrentIndex(0);
    }

private slots:
    void initTestCase()
    {
        test::useSoftwareRendering();
        QVERIFY(m_checklists.isValid());
    }
    void cleanup() { m_client.reset(); }

    void armWaitsForTheChecklist()
    {
        QFile file(m_checklists.filePath(QStringLiteral("default.json")));
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write(kChecklist) > 0);
        file.close();
        start();
        if (QTest::currentTestFailed())
            return;
        vehicle::Vehicle *v = m_client->fleet().vehicleAt(0);
        QTRY_VERIFY_WITH_TIMEOUT(v->position().isValid() && v->home().isValid(), 10000);
        // The button says what is left to do: the tick (Arm) and the route (Auto).
        QTRY_COMPARE_WITH_TIMEOUT(text("checklistButton"), QStringLiteral("Checklist: 2 to do"), 10000);

        // Arm: held back, and why; cancelled, nothing was asked of the vehicle.
        click(QStringLiteral("armButton"));
        QTRY_VERIFY(opened("checklistOverrideDialog"));
        QCOMPARE(text("checklistOverrideReasons"), QStringLiteral("• Propellers fitted and tight: to tick"));
        QVERIFY(!opened("commandConfirmDialog"));
        click(QStringLiteral("checklistOverrideCancel"));
        QTRY_VERIFY(!opened("checklistOverrideDialog"));
        QCOMPARE(logged(QStringLiteral("arm")), 0);
        QVERIFY(!v->armed());
        // The policy refuses it too, whoever asks (a script, a gamepad, a group command).
        QVERIFY(!m_client->fleet().commands()->send(client::CommandPolicy::Command::Arm, v));
        QCOMPARE(logged(QStringLiteral("arm")), 0);

        // Ticked in the checklist popup: ready, and Arm goes through the ordinary confirmation.
        click(QStringLiteral("checklistButton"));
        QTRY_VERIFY(opened("checklistPopup"));
        QCOMPARE(text("checklistName"), QStringLiteral("Field list"));
        QCOMPARE(text("checklistSource"), m_checklists.filePath(QStringLiteral("default.json")));
        QCOMPARE(text("checklistReadiness"), QStringLiteral("Not ready to arm: 3 of 5 pass"));
        click(QStringLiteral("checklistTick3"));
        QTRY_COMPARE(text("checklistReadiness"), QStringLiteral("Ready to arm; Auto waits"));
        QCOMPARE(text("checklistButton"), QStringLiteral("Checklist: 1 to do"));
        QTest::keyClick(m_client->window(), Qt::Key_Escape);
        QTRY_VERIFY(!opened("checklistPopup"));
        click(QStringLiteral("armButton"));
        QTRY_VERIFY(opened("commandConfirmDialog"));
        QVERIFY(!opened("checklistOverrideDialog"));
        QMetaObject::invokeMethod(m_client->find<QObject>(QStringLiteral("commandConfirmDialog")), "accept");
        QTRY_VERIFY_WITH_TIMEOUT(v->armed(), 10000);
        QCOMPARE(logged(QStringLiteral("arm")), 1);

        // Auto: Sortie has given it no route. Sent anyway: the override is in the command log
        // before the command, and the flight log keeps it.
        click(QStringLiteral("autoButton"));
        QTRY_VERIFY(opened("checklistOverrideDialog"));
        QCOMPARE(text("checklistOverrideReasons"), QStringLiteral("• Route on board: Sortie has uploaded no route to it"));
        click(QStringLiteral("checklistOverrideButton"));
        QTRY_VERIFY(!opened("checklistOverrideDialog"));
        const QString override = QStringLiteral("Auto sent despite the checklist (the operator overrode it): Route on board: Sortie has uploaded no route to it");
        const vehicle::CommandLog &log = *m_client->fleet().commandLog();
        QTRY_VERIFY(log.count() >= 3);
        int at = -1;
        for (int i = 0; i < log.count(); ++i)
            if (log.at(i).status == vehicle::CommandLog::Status::Alert && log.at(i).command == override)
                at = i;
        QVERIFY2(at >= 0, qPrintable(log.at(log.count() - 1).command));
        QVERIFY2(at + 1 < log.count() && log.at(at + 1).command.startsWith(QLatin1String("mode")), qPrintable(log.at(log.count() - 1).command));

        flightlog::FlightRecorder &recorder = m_client->graph().recorder();
        const QString path = recorder.path();
        QVERIFY(!path.isEmpty());
        QTest::qWait(300); // the recorder flushes every 100 ms
        recorder.stop();
        QString error;
        const auto recorded = flightlog::FlightLog::open(path, &error);
        QVERIFY2(recorded, qPrintable(error));
        QStringList alerts;
        for (const flightlog::FlightLog::Event &e : recorded->events())
            if (e.kind == QLatin1String("alert"))
                alerts << e.text;
        QVERIFY2(alerts.contains(override), qPrintable(alerts.join(QLatin1Char('\n'))));

        // Disarmed after having been armed: the ticks are cleared, the next flight is checked again.
        QVERIFY(m_client->fleet().commands()->send(client::CommandPolicy::Command::Disarm, v));
        QTRY_VERIFY_WITH_TIMEOUT(!v->armed(), 10000);
        QTRY_COMPARE(text("checklistButton"), QStringLiteral("Checklist: 2 to do"));
        QVERIFY(!m_client->fleet().commands()->send(client::CommandPolicy::Command::Arm, v));
    }

    void aFileWithAMistakeIsNotUsed()
    {
        QFile file(m_checklists.filePath(QStringLiteral("default.json")));
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(R"({"items": [{"check": "wind"}]})") > 0);
        file.close();
        start();
        if (QTest::currentTestFailed())
            return;
        click(QStringLiteral("checklistButton"));
        QTRY_VERIFY(opened("checklistPopup"));
        QVERIFY2(text("checklistSource").contains(QStringLiteral("default.json (at /items/0/check): unknown value \"wind\"")),
                 qPrintable(text("checklistSource")));
        QCOMPARE(text("checklistName"), QStringLiteral("Sortie's default checklist"));
        // Put right and read again: the operator's list is used.
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(kChecklist) > 0);
        file.close();
        click(QStringLiteral("checklistReloadButton"));
        QTRY_COMPARE(text("checklistName"), QStringLiteral("Field list"));
        QCOMPARE(text("checklistSource"), m_checklists.filePath(QStringLiteral("default.json")));
    }
};

QTEST_MAIN(TestChecklistFlow)
#include "tst_checklistflow.moc"
