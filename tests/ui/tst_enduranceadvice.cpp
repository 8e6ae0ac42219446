// The fly view's "time to come home", offscreen in the real window against a simulated VCI vehicle
// over a real socket: a 5 Wh battery (the sim's powers, so it drains in seconds) and the same energy
// profile loaded into the client's RouteEndurance. The vehicle takes off and flies away from home;
// the advisory goes amber, then red, each once in the command log; the banner's Return home asks
// first (the command bar's dialog) and then the vehicle returns home. No timed assertion: the sim
// is sped up, and slowed near the amber band only so the test sees it rather than races past it.
#include "ClientWindow.h"
#include "EnduranceAdvisory.h"
#include "QuickScene.h"
#include "RouteEndurance.h"
#include "SimVciVehicle.h"
#include "VehicleLayer.h"

#include <QDir>
#include <QFile>
#include <QGuiApplication>
#include <QPalette>
#include <QTemporaryDir>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;
using Level = endurance::EnduranceAdvisory::Level;

namespace {
// sortie-sim's powers with a 5 Wh battery: 1 Wh reserve, the amber band 0.5 Wh above it. Flying
// away at 5 m/s spends about 0.1 Wh a second of margin (out at 228 W, and 26 J more home per metre).
endurance::EnergyProfile smallBattery()
{
    endurance::EnergyProfile p = sim::simEnergyProfile();
    p.name = QStringLiteral("Sim quad, small battery");
    p.batteryWh = 5;
    return p;
}

QString screenshotPath(const QString &name)
{
    const QDir dir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR)));
    dir.mkpath(QStringLiteral("."));
    return dir.filePath(name);
}
} // namespace

class TestEnduranceAdvice : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_client;

    QPoint centreOf(QQuickItem *item) const
    {
        return item->mapToScene(QPointF(item->width() / 2, item->height() / 2)).toPoint();
    }
    // An item of the window, or of the alert banner's rows (Repeater delegates: not findChild's).
    QQuickItem *item(const char *name) const
    {
        if (QQuickItem *found = m_client->find(QString::fromLatin1(name)))
            return found;
        return test::findItem(m_client->find(QStringLiteral("alertBanner")), QString::fromLatin1(name));
    }
    void click(const char *name)
    {
        QQuickItem *item = this->item(name);
        QVERIFY2(item, name);
        QTRY_VERIFY2(item->isVisible() && item->isEnabled(), name);
        QTest::mouseClick(m_client->window(), Qt::LeftButton, {}, centreOf(item));
    }
    void confirm(const QString &mentioning)
    {
        QObject *dialog = m_client->find<QObject>(QStringLiteral("commandConfirmDialog"));
        QTRY_VERIFY(dialog->property("opened").toBool());
        QVERIFY2(dialog->property("text").toString().contains(mentioning), qPrintable(dialog->property("text").toString()));
        QMetaObject::invokeMethod(dialog, "accept");
        QTRY_VERIFY(!dialog->property("opened").toBool());
    }
    QString text(const char *name) const
    {
        QQuickItem *found = item(name);
        return found ? found->property("text").toString() : QStringLiteral("(no %1)").arg(QLatin1String(name));
    }
    void shoot(const QString &name)
    {
        QVERIFY(test::waitForFrame(m_client->window()));
        const QImage image = m_client->window()->grabWindow();
        QVERIFY(!image.isNull());
        QVERIFY(image.save(screenshotPath(name)));
    }
    // Lines of the command log that are the advisory's.
    QStringList adviceLines() const
    {
        QStringList lines;
        const vehicle::CommandLog &log = *m_client->fleet().commandLog();
        for (int i = 0; i < log.count(); ++i)
            if (log.at(i).command.startsWith(QStringLiteral("Battery: time to come home")))
                lines << log.at(i).command;
        return lines;
    }

private slots:
    void initTestCase() { test::useSoftwareRendering(); }
    void cleanupTestCase() { m_client.reset(); }

    void amberThenRedThenReturnHome()
    {
        test::ClientWindow::Options options;
        options.vciTimeScale = 4;
        options.vciEnergy = smallBattery();
        m_client = std::make_unique<test::ClientWindow>(options);
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
        sim::SimVciVehicle &sim = *m_client->vci().vehicles().front();

        // The operator's profile file for this vehicle, as the mission page loads it.
        QTemporaryDir dir;
        const QString profile = dir.filePath(QStringLiteral("small.json"));
        QFile f(profile);
        QVERIFY(f.open(QIODevice::WriteOnly) && f.write(endurance::writeEnergyProfile(smallBattery())) > 0);
        f.close();
        QVERIFY2(m_client->graph().endurance().loadProfile(profile), qPrintable(m_client->graph().endurance().problem()));

        QVERIFY(m_client->addVciVehicles());
        QTest::keyClick(m_client->window(), Qt::Key_3, Qt::ControlModifier);
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        QTRY_COMPARE(layer->positionedCount(), 1);
        layer->setCurrentIndex(0);
        vehicle::Vehicle *v = m_client->fleet().vehicleAt(0);
        auto *advisory = m_client->find<endurance::EnduranceAdvisory>(QStringLiteral("enduranceAdvisory"));
        QVERIFY(advisory);
        QTRY_COMPARE(advisory->vehicle(), v);

        // On the ground at home, full: Normal, home needs nothing to speak of; no mission on board,
        // so the end of the route is missing, not 0 %.
        QTRY_COMPARE_WITH_TIMEOUT(advisory->level(), Level::Normal, 10000);
        QTRY_VERIFY(text("enduranceLine").startsWith(QStringLiteral("Battery at end of route: — · home needs ")));
        QVERIFY(!m_client->find(QStringLiteral("alertBanner"))->isVisible());

        // Arm and take off through the command bar, then fly 3 km east at 5 m/s.
        // The pre-flight checklist passes once the vehicle's slower telemetry (GPS, battery) is in.
        QTRY_VERIFY_WITH_TIMEOUT(m_client->fleet().commands()->blockers(client::CommandPolicy::Command::Arm, v).isEmpty(), 10000);
        click("armButton");
        confirm(v->name());
        QTRY_VERIFY_WITH_TIMEOUT(v->armed(), 10000);
        click("takeoffButton");
        confirm(v->name());
        QTRY_VERIFY_WITH_TIMEOUT(v->altitudeAgl() > 15, 20000);
        const QGeoCoordinate home = v->home();
        QVERIFY(home.isValid());
        m_client->fleet().goTo(0, home.latitude(), home.longitude() + 0.05);

        // Near the band, the sim slows to real time, so the amber spell lasts seconds.
        QTRY_VERIFY_WITH_TIMEOUT(advisory->margin().isValid() && advisory->margin().toDouble() < 1.5, 60000);
        sim.knobs().timeScale = 1;
        auto *banner = m_client->find(QStringLiteral("alertBanner"));
        QTRY_COMPARE_WITH_TIMEOUT(advisory->level(), Level::Amber, 30000);
        QTRY_VERIFY(banner->isVisible());
        QVERIFY(text("enduranceAdvice").contains(QStringLiteral("to spare")));
        QTRY_COMPARE(adviceLines().size(), 1);
        shoot(QStringLiteral("advice-amber.png"));

        sim.knobs().timeScale = 4;
        QTRY_COMPARE_WITH_TIMEOUT(advisory->level(), Level::Red, 60000);
        QTRY_VERIFY(text("enduranceAdvice").contains(QStringLiteral("reserve is being used")));
        QTRY_COMPARE(adviceLines().size(), 2);
        QVERIFY(adviceLines().at(1).contains(QStringLiteral("reserve is being used")));
        sim.knobs().timeScale = 1;  // it keeps flying away until told; no need to hurry now
        shoot(QStringLiteral("advice-red.png"));

        // One click opens the question; nothing is sent before it is answered.
        click("adviceReturnHomeButton");
        QObject *dialog = m_client->find<QObject>(QStringLiteral("commandConfirmDialog"));
        QTRY_VERIFY(dialog->property("opened").toBool());
        QTest::qWait(300);
        QVERIFY(v->mode() != QStringLiteral("return_home"));
        shoot(QStringLiteral("advice-confirm.png"));
        confirm(QStringLiteral("Return %1 home").arg(v->name()));
        QTRY_COMPARE_WITH_TIMEOUT(v->mode(), QStringLiteral("return_home"), 10000);
        QCOMPARE(adviceLines().size(), 2);  // still red, not repeated
        // And it does come back: closer to home than when it was told.
        const double told = v->position().distanceTo(home);
        sim.knobs().timeScale = 4;
        QTRY_VERIFY_WITH_TIMEOUT(v->position().distanceTo(home) < told - 30, 30000);
        QCOMPARE(v->mode(), QStringLiteral("return_home"));
        QTRY_COMPARE(text("value_mode"), QStringLiteral("return_home"));
        sim.knobs().timeScale = 1;

        // The same in the dark palette.
        QGuiApplication::setPalette(sortie::test::darkPalette());
        QTRY_VERIFY(m_client->window()->property("dark").toBool());
        if (banner->isVisible())
            shoot(QStringLiteral("advice-red-dark.png"));
        QGuiApplication::setPalette(QPalette());
    }
};

QTEST_MAIN(TestEnduranceAdvice)
#include "tst_enduranceadvice.moc"
