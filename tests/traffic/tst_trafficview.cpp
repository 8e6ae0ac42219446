// Manned traffic on the map, offscreen: the client's own window (its ClientGraph) against the
// embedded simulator draws the simulator's aircraft in the fly view, from the server's ADS-B list
// and an SBS-1 feed at once (merged: one mark per aircraft), each with its chevron and a label that
// overlaps no other; and an aircraft not heard for a minute is drawn faded.
#include "ClientWindow.h"
#include "MapPalette.h"
#include "HciClient.h"
#include "HciSession.h"
#include "QuickScene.h"
#include "SbsFeed.h"
#include "SimSbsServer.h"
#include "SimTraffic.h"
#include "Traffic.h"
#include "TrafficLayer.h"
#include "TrafficPicture.h"
#include "VehicleLayer.h"

#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

// Pixels of `rect` within 40 of `colour` on every channel.
int countNear(const QImage &image, const QRectF &rect, const QColor &colour)
{
    int count = 0;
    const QRect r = rect.toAlignedRect().intersected(image.rect());
    for (int y = r.top(); y <= r.bottom(); ++y)
        for (int x = r.left(); x <= r.right(); ++x) {
            const QColor c = image.pixelColor(x, y);
            count += std::abs(c.red() - colour.red()) < 40 && std::abs(c.green() - colour.green()) < 40
                && std::abs(c.blue() - colour.blue()) < 40;
        }
    return count;
}

QRectF around(QPointF p, double half)
{
    return QRectF(p - QPointF(half, half), QSizeF(2 * half, 2 * half));
}

} // namespace

class TestTrafficView : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void theSimulatorsTrafficInTheFlyView()
    {
        test::ClientWindow app;
        QVERIFY2(app.isReady(), qPrintable(app.error()));
        sim::SimSbsServer sbs(app.world().traffic()); // as sortie --demo serves it
        QVERIFY(sbs.listen(QHostAddress::LocalHost, 0));
        app.graph().traffic().receiver()->setAddress(QStringLiteral("127.0.0.1:%1").arg(sbs.port()));
        QVERIFY(app.logIn());
        app.showPage(2);
        auto *layer = app.find<ui::TrafficLayer>(QStringLiteral("trafficLayer"));
        auto *vehicles = app.find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        QVERIFY(layer && vehicles && layer->map());
        vehicles->setAutoFit(false); // the view is the traffic's
        layer->map()->setCenter(QGeoCoordinate(sim::SimTraffic::kCentreLatitude, sim::SimTraffic::kCentreLongitude));
        layer->map()->setZoomLevel(12.4);

        const traffic::TrafficPicture *picture = app.graph().traffic().picture();
        const auto fromBoth = [picture] {
            return picture->count() == 3 && std::all_of(picture->aircraft().begin(), picture->aircraft().end(), [](const auto &a) {
                       return a.state.callsign && a.state.latitude && a.state.trackDeg && a.state.altitudeM;
                   });
        };
        QTRY_VERIFY_WITH_TIMEOUT(fromBoth(), 20000);
        QTRY_COMPARE_WITH_TIMEOUT(app.graph().traffic().server()->state(), traffic::HciTrafficSource::State::Answered, 20000);
        QCOMPARE(app.graph().traffic().receiver()->state(), traffic::SbsFeed::State::Connected);
        QTRY_COMPARE_WITH_TIMEOUT(layer->drawnCount(), 3, 10000);
        QVERIFY(test::waitForFrame(app.window()));
        const QImage image = app.window()->grabWindow();
        const QPointF origin = layer->mapToScene(QPointF(0, 0));
        const QColor colour = ui::MapPalette::light().traffic;
        QStringList callsigns;
        for (int i = 0; i < layer->drawnCount(); ++i) {
            callsigns << layer->labelText(i).section(QLatin1Char(' '), 0, 0);
            QVERIFY2(layer->labelText(i).contains(QStringLiteral(" m")), qPrintable(layer->labelText(i))); // its altitude
            const QPointF at = layer->aircraftPosition(i) + origin;
            if (!image.rect().contains(at.toPoint()))
                continue; // the far airliner may be past the edge
            QVERIFY2(countNear(image, around(at, 5), colour) > 5, qPrintable(layer->labelText(i))); // the chevron
            const QRectF label = layer->labelRect(i).translated(origin);
            QVERIFY2(countNear(image, label, colour.darker(160)) > 10, qPrintable(layer->labelText(i))); // its text
            for (int j = 0; j < i; ++j)
                QVERIFY(!layer->labelRect(i).intersects(layer->labelRect(j)));
        }
        callsigns.sort();
        QCOMPARE(callsigns, (QStringList{QStringLiteral("AFR64K"), QStringLiteral("BTI7TR"), QStringLiteral("YLHEL1")}));
        // The helicopter's orbit (900 m) is on screen at this zoom.
        bool helicopterShown = false;
        for (int i = 0; i < layer->drawnCount(); ++i)
            helicopterShown |= layer->labelText(i).startsWith(QStringLiteral("YLHEL1")) && image.rect().contains((layer->aircraftPosition(i) + origin).toPoint());
        QVERIFY(helicopterShown);
        const QString dir = qEnvironmentVariable("SORTIE_SCREENSHOT_DIR");
        if (!dir.isEmpty())
            image.save(dir + QStringLiteral("/traffic.png"));
    }

    // Not heard for a minute: drawn faded; heard again: drawn whole.
    void staleTrafficIsFaded()
    {
        test::QuickScene scene(R"(
import QtQuick
import Sortie.Ui
Item {
    MapView { id: map; objectName: "map"; anchors.fill: parent; latitude: 56.9765; longitude: 24.076; zoomLevel: 14 }
    TrafficLayer { objectName: "traffic"; anchors.fill: parent; map: map }
}
)", QSize(600, 400));
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *layer = scene.find<ui::TrafficLayer>(QStringLiteral("traffic"));
        QVERIFY(layer);
        qint64 now = 1000000;
        hci::HciSession session;
        hci::HciClient client(&session);
        traffic::Traffic traffic(nullptr, &client, {}, [&now] { return now; });
        layer->setTraffic(&traffic);
        const auto report = [&traffic](quint32 address, const char *callsign, double east) {
            traffic::TrafficReport r;
            r.address = address;
            r.callsign = QString::fromLatin1(callsign);
            r.latitude = 56.9765;
            r.longitude = 24.076 + east;
            r.altitudeM = 300;
            r.trackDeg = 0;
            r.groundSpeedMps = 40;
            r.verticalRateMps = 3;
            traffic.picture()->report(r);
        };
        report(0x502C01, "OLD1", -0.01);
        report(0x502C02, "NEW2", 0.01);
        now += traffic::TrafficPicture::kStaleAfterMs;
        report(0x502C02, "NEW2", 0.01);
        traffic.picture()->sweep();
        QCOMPARE(layer->drawnCount(), 2);
        QVERIFY(layer->isStale(0));
        QVERIFY(!layer->isStale(1));
        QCOMPARE(layer->labelText(1), QStringLiteral("NEW2 300 m std climbing"));
        QVERIFY(!layer->labelRect(0).intersects(layer->labelRect(1)));
        const QImage image = scene.grab();
        const QColor colour = ui::MapPalette::light().traffic;
        QVERIFY(countNear(image, around(layer->aircraftPosition(1), 4), colour) > 5);
        QCOMPARE(countNear(image, around(layer->aircraftPosition(0), 4), colour), 0); // faded: not the full colour
        now += traffic::TrafficPicture::kRemoveAfterMs - traffic::TrafficPicture::kStaleAfterMs;
        traffic.picture()->sweep();
        QCOMPARE(layer->drawnCount(), 1);
    }
};

QTEST_MAIN(TestTrafficView)
#include "tst_trafficview.moc"
