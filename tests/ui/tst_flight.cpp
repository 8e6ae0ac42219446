// The whole flight from the fly view, offscreen against the embedded simulator, for an HCI
// vehicle: plan (the demo route), upload with the progress bar moving, arm, take off, auto; the
// live view frames the vehicles and the instruments move (attitude, heading compass with the
// bearing to home, flight time, distance to home); pause, resume, return home, land. Every
// command goes through the buttons and the confirmation dialog, as an operator gives it.
#include "AttitudeIndicator.h"
#include "ClientWindow.h"
#include "FlightStatus.h"
#include "HeadingCompass.h"
#include "MapView.h"
#include "QuickScene.h"
#include "VehicleLayer.h"

#include <QDir>
#include <QSignalSpy>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

class TestFlight : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_client;

    QPoint centreOf(QQuickItem *item) const
    {
        return item->mapToScene(QPointF(item->width() / 2, item->height() / 2)).toPoint();
    }
    void click(const char *name)
    {
        auto *item = m_client->find(QString::fromLatin1(name));
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
    QString text(const char *name) const { return m_client->find<QObject>(QString::fromLatin1(name))->property("text").toString(); }

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void init()
    {
        m_client = std::make_unique<test::ClientWindow>();
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
    }
    void cleanup() { m_client.reset(); }

    void flyTheDemoRouteOnAnHciVehicle()
    {
        QVERIFY(m_client->logIn());
        QTRY_COMPARE(m_client->window()->property("currentPage").toInt(), 1); // on to the mission
        QVERIFY(m_client->openDemoRoute());

        // Upload to EMU-101, the progress bar moving.
        QObject *vehicles = m_client->find<QObject>(QStringLiteral("vehiclePicker"));
        QTRY_COMPARE(vehicles->property("count").toInt(), 3);
        vehicles->setProperty("currentIndex", 0);
        QObject *bar = m_client->find<QObject>(QStringLiteral("progressBar"));
        QList<double> values;
        connect(&m_client->missions(), &client::MissionController::progressChanged, bar, [&values, bar] {
            if (bar->property("to").toDouble() > 1)
                values.append(bar->property("value").toDouble());
        });
        QSignalSpy uploaded(&m_client->missions(), &client::MissionController::uploaded);
        click("uploadButton");
        QVERIFY(uploaded.wait(20000));
        QVERIFY2(values.size() >= 3 && values.last() > values.first(), qPrintable(QString::number(values.size())));

        // The fly view: opens framed on the vehicles (not the world at zoom 2).
        QTest::keyClick(m_client->window(), Qt::Key_3, Qt::ControlModifier);
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        auto *map = m_client->page("telemetryPage")->property("map").value<ui::MapView *>();
        QTRY_COMPARE_WITH_TIMEOUT(layer->positionedCount(), 3, 10000);
        QTRY_VERIFY(map->zoomLevel() > 12);
        for (int row = 0; row < 3; ++row)
            QVERIFY(QRectF(0, 0, map->width(), map->height()).contains(layer->vehiclePosition(row)));

        // Choose EMU-101 in the list: it is centred, its instruments fill in.
        const int row = [&] {
            for (int r = 0; r < m_client->fleet().count(); ++r)
                if (m_client->fleet().vehicleAt(r)->name() == QLatin1String("EMU-101"))
                    return r;
            return -1;
        }();
        QVERIFY(row >= 0);
        vehicle::Vehicle *emu = m_client->fleet().vehicleAt(row);
        auto *list = m_client->find(QStringLiteral("vehicleList"));
        QQuickItem *delegate = nullptr;
        QMetaObject::invokeMethod(list, "itemAtIndex", Q_RETURN_ARG(QQuickItem *, delegate), Q_ARG(int, row));
        QVERIFY(delegate);
        QTest::mouseClick(m_client->window(), Qt::LeftButton, {}, centreOf(delegate));
        QTRY_COMPARE(layer->currentIndex(), row);
        const QPointF centre(map->width() / 2, map->height() / 2);
        QTRY_VERIFY((layer->vehiclePosition(row) - centre).manhattanLength() < 3);
        QTRY_VERIFY(text("value_batteryVoltage").endsWith(QStringLiteral(" V"))); // the simulator sends volts only
        auto *status = m_client->find<QObject>(QStringLiteral("instrumentPanel"))->property("status").value<ui::FlightStatus *>();
        QVERIFY(status);
        QCOMPARE(text("value_armedTime"), QStringLiteral("—")); // not armed: no flight time, not 0:00

        // Arm and take off, each confirmed.
        click("armButton");
        confirm(QStringLiteral("EMU-101"));
        QTRY_VERIFY_WITH_TIMEOUT(emu->armed(), 10000);
        click("takeoffButton");
        confirm(QStringLiteral("EMU-101"));
        QTRY_VERIFY_WITH_TIMEOUT(emu->altitudeAgl() > 5, 30000);
        QTRY_VERIFY(std::isfinite(status->flightSeconds()));
        QTRY_VERIFY(text("value_armedTime") != QStringLiteral("—"));

        // Auto: it flies the route; the compass turns, home falls behind, the attitude moves.
        auto *compass = m_client->find<ui::HeadingCompass>(QStringLiteral("headingCompass"));
        auto *attitude = m_client->find<ui::AttitudeIndicator>(QStringLiteral("attitudeIndicator"));
        QVERIFY(compass && attitude);
        click("autoButton");
        confirm(QStringLiteral("Start the mission on EMU-101"));
        QTRY_COMPARE_WITH_TIMEOUT(emu->mode(), QStringLiteral("auto"), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(status->distanceToHome() > 15, 30000);
        QVERIFY(std::isfinite(compass->heading()));
        QVERIFY(std::isfinite(compass->bearingToHome()));
        QVERIFY(attitude->hasAttitude());
        QVERIFY(text("value_home") != QStringLiteral("—"));
        QTest::qWait(150); // let the trail and the instruments draw once more for the picture
        m_client->window()->grabWindow().save(
            QDir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR))).filePath(QStringLiteral("fly.png")));

        // Follow keeps it in the middle while it flies.
        click("followButton");
        QVERIFY(layer->follow());
        const QRectF middle(map->width() / 4, map->height() / 4, map->width() / 2, map->height() / 2);
        QTRY_VERIFY(middle.contains(layer->vehiclePosition(row)));

        // Pause and resume.
        click("pauseButton");
        QTRY_COMPARE_WITH_TIMEOUT(emu->mode(), QStringLiteral("hold"), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(emu->groundSpeed() < 0.5, 20000);
        click("resumeButton"); // resuming starts the mission again: asked like Auto
        confirm(QStringLiteral("Start the mission on EMU-101"));
        QTRY_COMPARE_WITH_TIMEOUT(emu->mode(), QStringLiteral("auto"), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(emu->groundSpeed() > 1, 20000);

        // Home, then land where it is: commands that make it safer go at once (CommandPolicy), no dialog.
        QObject *dialog = m_client->find<QObject>(QStringLiteral("commandConfirmDialog"));
        click("homeButton");
        QVERIFY(!dialog->property("opened").toBool());
        QTRY_COMPARE_WITH_TIMEOUT(emu->mode(), QStringLiteral("return_home"), 10000);
        click("landButton");
        QVERIFY(!dialog->property("opened").toBool());
        QTRY_COMPARE_WITH_TIMEOUT(emu->mode(), QStringLiteral("land"), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(emu->verticalSpeed() < -0.2, 20000);
    }
};

QTEST_MAIN(TestFlight)
#include "tst_flight.moc"
