// The fly view's offer to resume, in the client's real window (offscreen) against the embedded
// simulator's VCI vehicle: a scan uploaded and flown part of the way, the vehicle sent home; once it
// stands disarmed the fly view offers the rest, and a click opens it in the mission editor, chosen
// for that vehicle, where every rule checks it.
#include "ClientWindow.h"
#include "ResumeTestRoute.h"

#include "Geodesy.h"
#include "MissionController.h"
#include "SimVciFleet.h"
#include "SimVciListener.h"
#include "MissionResume.h"
#include "RouteAnalyzer.h"
#include "RouteDocument.h"
#include "RoutePreparation.h"
#include "VehicleFleet.h"
#include "VehicleLayer.h"
#include "VehicleLink.h"

#include <QDir>
#include <QSignalSpy>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

class TestResumeView : public QObject
{
    Q_OBJECT
    std::unique_ptr<test::ClientWindow> m_client;

    QPoint centreOf(QQuickItem *item) const { return item->mapToScene(QPointF(item->width() / 2, item->height() / 2)).toPoint(); }
    void click(const char *name)
    {
        auto *item = m_client->find(QString::fromLatin1(name));
        QVERIFY2(item, name);
        QTRY_VERIFY2(item->isVisible() && item->isEnabled(), name);
        QTest::mouseClick(m_client->window(), Qt::LeftButton, {}, centreOf(item));
    }
    QString text(const char *name) const { return m_client->find<QObject>(QString::fromLatin1(name))->property("text").toString(); }
    static void obey(vehicle::VehicleLink *link, const std::function<void(vehicle::VehicleLink::Done)> &command)
    {
        bool done = false;
        vehicle::CommandResult result;
        command([&](const vehicle::CommandResult &r) {
            done = true;
            result = r;
        });
        QTRY_VERIFY(done);
        QVERIFY2(result.ok, qPrintable(result.message));
    }

private slots:
    void offersTheRestOnceTheVehicleStandsDown()
    {
        test::ClientWindow::Options options;
        options.vciHome = QGeoCoordinate(test::kResumeHome.latitude, test::kResumeHome.longitude);
        options.vciTimeScale = 20;
        options.mannedTraffic = false;
        m_client = std::make_unique<test::ClientWindow>(options);
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
        QVERIFY(m_client->logIn());
        QVERIFY(m_client->fleet().addVciVehicle(QStringLiteral("tcp://127.0.0.1:%1").arg(m_client->vci().listeners().front()->port())));
        client::VehicleFleet &fleet = m_client->fleet();
        int row = -1;
        QTRY_VERIFY_WITH_TIMEOUT((row = [&] {
            for (int r = 0; r < fleet.count(); ++r)
                if (fleet.vehicleAt(r)->protocol() == QLatin1String("VCI") && fleet.vehicleAt(r)->isConnected() && fleet.vehicleAt(r)->position().isValid())
                    return r;
            return -1;
        }()) >= 0, 10000);
        vehicle::Vehicle *v = fleet.vehicleAt(row);

        // The survey, uploaded from the mission editor to the VCI vehicle, flown part of the way.
        const mission::Route route = test::resumeTestRoute();
        client::RouteDocument *document = m_client->missions().document();
        document->open(route, QStringLiteral("the survey"));
        client::RoutePreparation *preparation = m_client->missions().preparation();
        m_client->showPage(1);
        QObject *picker = m_client->find<QObject>(QStringLiteral("vehiclePicker"));
        QTRY_COMPARE(picker->property("count").toInt(), fleet.count());
        picker->setProperty("currentIndex", row); // the chooser lists the fleet, in its order
        QCOMPARE(preparation->vehicleId(), v->fleetId());
        QSignalSpy uploaded(preparation, &client::RoutePreparation::uploaded);
        click("uploadButton");
        QVERIFY2(uploaded.wait(20000), qPrintable(text("preparationMessage")));
        vehicle::VehicleLink *link = v->link();
        obey(link, [&](auto done) { link->arm(true, done); });
        obey(link, [&](auto done) { link->setMode(vehicle::FlightMode::Auto, done); });
        QTRY_VERIFY_WITH_TIMEOUT(v->photoCount() >= 40, 60000);
        obey(link, [&](auto done) { link->returnHome(done); });

        // In the fly view, with the vehicle chosen: nothing offered while it flies home.
        QTest::keyClick(m_client->window(), Qt::Key_3, Qt::ControlModifier);
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        layer->setProperty("currentIndex", row);
        QQuickItem *panel = m_client->find(QStringLiteral("resumePanel"));
        QVERIFY(panel);
        QVERIFY(!panel->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(!v->armed(), 60000);
        QTRY_VERIFY(panel->isVisible());
        const int photos = v->photoCount();
        QVERIFY2(text("resumeSummary").startsWith(QStringLiteral("Field 7 stopped flying to waypoint ")), qPrintable(text("resumeSummary")));
        QVERIFY2(text("resumeSummary").endsWith(QStringLiteral(", after %1 photos.").arg(photos)), qPrintable(text("resumeSummary")));
        if (qEnvironmentVariableIsSet("SORTIE_SCREENSHOT_DIR"))
            m_client->window()->grabWindow().save(QDir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR")).filePath(QStringLiteral("resume-offer.png")));

        // From the last photo: the rest opens in the mission editor, for this vehicle (the chooser
        // had another by then), checked.
        picker->setProperty("currentIndex", row == 0 ? 1 : 0);
        QVERIFY(preparation->vehicleId() != v->fleetId());
        click("resumeFromPhotoButton");
        QTRY_COMPARE(m_client->window()->property("currentPage").toInt(), 1);
        QCOMPARE(document->route().settings.name, QStringLiteral("Field 7 (resumed)"));
        QCOMPARE(preparation->vehicleId(), v->fleetId());
        QCOMPARE(picker->property("currentIndex").toInt(), row);
        const auto &segments = document->route().segments;
        QVERIFY(segments.size() > 4);
        QCOMPARE(std::get<mission::Waypoint>(segments.front()).role, mission::WaypointRole::Takeoff);
        QVERIFY(mission::geodesicDistance(std::get<mission::Waypoint>(segments.front()).position,
                                          {v->position().latitude(), v->position().longitude()}) < 3);
        QCOMPARE(segments.back(), route.segments.back());
        QTRY_COMPARE(document->analyzer()->errorCount(), 0);
        QVERIFY(m_client->graph().resume()->notes().join(u' ').contains(QStringLiteral("starts again at the resume point")));
    }
};

QTEST_MAIN(TestResumeView)
#include "tst_resumeview.moc"
