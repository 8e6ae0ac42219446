// Deconfliction where the operator plans, offscreen with the program's own wiring against the
// embedded simulator: EMU-101 flies a route east along a line; the open route, chosen for EMU-102,
// flies the same line west at the same height. The mission view draws where they would meet (the
// conflict layer's ring, in red, on the open route), the route panel lists the conflict with its
// time, and pressing Upload refuses it, naming EMU-101; nothing reaches EMU-102.
#include "ClientWindow.h"
#include "MapPalette.h"
#include "ConflictLayer.h"
#include "FleetRoutes.h"
#include "MapView.h"
#include "MissionUploader.h"
#include "QuickScene.h"
#include "RouteDeconfliction.h"
#include "RouteDocument.h"
#include "RoutePreparation.h"
#include "VisualCheck.h"

#include <QDir>
#include <QSignalSpy>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

mission::Route lineRoute(const QGeoCoordinate &origin, double fromEast, double toEast, const QString &name)
{
    mission::Route route;
    route.settings.name = name;
    for (int i = 0; i <= 4; ++i) {
        const QGeoCoordinate p = origin.atDistanceAndAzimuth(fromEast + (toEast - fromEast) * i / 4, 90);
        mission::Waypoint w;
        w.position = {p.latitude(), p.longitude()};
        w.altitude = 25;
        w.speed = 6;
        route.segments.push_back(w);
    }
    return route;
}

} // namespace

class TestConflictView : public QObject
{
    Q_OBJECT

    vehicle::Vehicle *emu(test::ClientWindow &client, const QString &name) const
    {
        for (int row = 0; row < client.fleet().count(); ++row) {
            vehicle::Vehicle *v = client.fleet().vehicleAt(row);
            if (v->name() == name && v->isConnected() && v->position().isValid())
                return v;
        }
        return nullptr;
    }
    static QString idOf(const vehicle::Vehicle *v) { return v->protocol() + QLatin1Char(':') + v->id(); }

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void aRouteThatMeetsAFlyingVehicleIsDrawnAndRefused()
    {
        test::ClientWindow client{test::ClientWindow::Options{}};
        QVERIFY2(client.isReady(), qPrintable(client.error()));
        QVERIFY(client.logIn());
        QTRY_VERIFY_WITH_TIMEOUT(emu(client, QStringLiteral("EMU-101")) && emu(client, QStringLiteral("EMU-102")), 10000);
        vehicle::Vehicle *first = emu(client, QStringLiteral("EMU-101"));
        vehicle::Vehicle *second = emu(client, QStringLiteral("EMU-102"));
        const QGeoCoordinate origin = first->position();
        client::RoutePreparation *preparation = client.missions().preparation();
        client::MissionUploader *uploader = preparation->uploader();

        // EMU-101: eastbound, uploaded, then flying.
        client.missions().document()->load(lineRoute(origin, 10, 250, QStringLiteral("Eastbound")));
        preparation->setVehicleId(idOf(first));
        QSignalSpy finished(uploader, &client::MissionUploader::finished);
        preparation->upload();
        QTRY_VERIFY_WITH_TIMEOUT(!finished.isEmpty() || uploader->isAsking(), 15000);
        if (uploader->isAsking())
            uploader->confirm();
        QTRY_COMPARE_WITH_TIMEOUT(uploader->state(), client::MissionUploader::State::Done, 15000);
        first->arm();
        QTRY_VERIFY_WITH_TIMEOUT(first->armed(), 10000);
        first->setMode(QStringLiteral("auto"));
        QTRY_VERIFY_WITH_TIMEOUT(client.graph().fleetRoutes()->routes().front().state == client::FleetRouteState::Flying, 20000);

        // The open route for EMU-102: westbound on the same line.
        client.showPage(1);
        client.missions().document()->load(lineRoute(origin, 250, 10, QStringLiteral("Westbound")));
        preparation->setVehicleId(idOf(second));
        auto *layer = client.find<ui::ConflictLayer>(QStringLiteral("conflictLayer"));
        QVERIFY(layer);
        QTRY_VERIFY_WITH_TIMEOUT(layer->markCount() >= 1, 20000);
        QVERIFY(client.graph().deconfliction()->count() >= 1);
        // The conflict timeline's rows (Repeater delegates: the timeline's child items, not its QObject children).
        QQuickItem *timeline = client.find(QStringLiteral("conflictTimeline"));
        QVERIFY(timeline);
        QTRY_VERIFY(timeline->isVisible());
        QQuickItem *row = nullptr;
        for (QQuickItem *child : timeline->childItems())
            if (child->objectName() == QStringLiteral("conflictRow"))
                row = child;
        QVERIFY(row && row->isVisible());
        const QString rowText = row->property("text").toString();
        QVERIFY2(rowText.contains(QStringLiteral("EMU-101")) && rowText.contains(QStringLiteral("flying")), qPrintable(rowText));

        // Framed on the line, the ring is drawn in the conflict colour where the layer says.
        auto *map = client.page("missionPage")->property("map").value<ui::MapView *>();
        const QGeoCoordinate east = origin.atDistanceAndAzimuth(260, 90);
        map->fitBounds(std::min(origin.latitude(), east.latitude()) - 0.001, origin.longitude() - 0.001,
                       std::max(origin.latitude(), east.latitude()) + 0.001, east.longitude() + 0.001, 60);
        QTest::qWait(200);
        const QImage image = client.window()->grabWindow();
        image.save(QDir(qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR))).filePath(QStringLiteral("conflict.png")));
        const QPointF ring = layer->mapToScene(layer->markPosition(0));
        int red = 0;
        for (int dy = -12; dy <= 12; ++dy)
            for (int dx = -12; dx <= 12; ++dx) {
                const QPoint p = (ring + QPointF(dx, dy)).toPoint();
                red += image.rect().contains(p) && test::colourDistance(image.pixel(p), ui::MapPalette::light().conflict.rgb()) < 60;
            }
        QVERIFY2(red > 10, qPrintable(QString::number(red)));

        // Upload: refused, saying why; nothing reaches EMU-102.
        finished.clear();
        int secondRow = -1;
        for (int r = 0; r < client.fleet().count(); ++r)
            if (client.fleet().vehicleAt(r) == second)
                secondRow = r;
        client.find<QObject>(QStringLiteral("vehiclePicker"))->setProperty("currentIndex", secondRow); // as the operator picks it
        QCOMPARE(preparation->vehicleId(), idOf(second));
        QQuickItem *upload = client.find(QStringLiteral("uploadButton"));
        QVERIFY(upload);
        QTRY_VERIFY(upload->isVisible() && upload->isEnabled());
        QTest::mouseClick(client.window(), Qt::LeftButton, {}, upload->mapToScene(QPointF(upload->width() / 2, upload->height() / 2)).toPoint());
        QTRY_VERIFY_WITH_TIMEOUT(!finished.isEmpty(), 15000);
        QVERIFY(uploader->state() != client::MissionUploader::State::Done);
        const QString message = client.find<QObject>(QStringLiteral("preparationMessage"))->property("text").toString();
        QVERIFY2(message.contains(QStringLiteral("EMU-101")), qPrintable(message));
        QVERIFY(second->mission().empty());
    }
};

QTEST_MAIN(TestConflictView)
#include "tst_conflictview.moc"
