// The fly view's parts, each in a real offscreen scene with Vehicles fed by hand: FlightStatus
// (progress, home, flight time, battery levels, link rate), the attitude indicator and the heading
// compass drawn offscreen, the flight-plan layer (flown, ahead, active waypoint), and the plot with
// several fields (an axis per unit) and several vehicles.
#include "AttitudeIndicator.h"
#include "FlightPlanLayer.h"
#include "FlightStatus.h"
#include "HeadingCompass.h"
#include "MapView.h"
#include "QuickScene.h"
#include "TelemetryPlot.h"
#include "Vehicle.h"
#include "VehiclePalette.h"

#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <cmath>
#include <numbers>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;
using vehicle::TelemetryField;
using F = TelemetryField;

namespace {
vehicle::MissionItem waypoint(double latDeg, double lonDeg)
{
    return {latDeg, lonDeg, 30, 5, 0, {}};
}

// Where the vehicle is (degrees), its home, and anything else, at `time` ms.
void report(vehicle::Vehicle &v, int64_t time, double lat, double lon, vehicle::TelemetryBatch more = {})
{
    vehicle::TelemetryBatch batch{{F::Latitude, lat, time}, {F::Longitude, lon, time},
                                  {F::HomeLatitude, 56.95, time}, {F::HomeLongitude, 24.10, time}};
    batch.insert(batch.end(), more.begin(), more.end());
    v.ingest(batch);
}

int countNear(const QImage &image, const QRect &rect, const QColor &colour, int tolerance = 40)
{
    int count = 0;
    for (int y = std::max(0, rect.top()); y <= std::min(image.height() - 1, rect.bottom()); ++y)
        for (int x = std::max(0, rect.left()); x <= std::min(image.width() - 1, rect.right()); ++x)
            count += test::colourDistance(image.pixel(x, y), colour.rgb()) < tolerance ? 1 : 0;
    return count;
}

const QByteArray kInstruments = R"(
import QtQuick
import Sortie.Ui
Row {
    AttitudeIndicator { objectName: "attitude"; width: 160; height: 160 }
    HeadingCompass { objectName: "compass"; width: 160; height: 160 }
}
)";

const QByteArray kMapScene = R"(
import QtQuick
import Sortie.Ui
Item {
    MapView { id: map; objectName: "map"; anchors.fill: parent; latitude: 56.951; longitude: 24.101; zoomLevel: 16 }
    FlightPlanLayer { objectName: "plans"; anchors.fill: parent; map: map }
}
)";
} // namespace

class TestFlyView : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void flightStatusFollowsTheVehicle()
    {
        vehicle::Vehicle v(nullptr);
        v.setNotifyInterval(0);
        ui::FlightStatus status;
        status.setVehicle(&v);
        // Nothing known yet: missing, never 0.
        QCOMPARE(status.progressText(), QStringLiteral("no mission on board"));
        QVERIFY(std::isnan(status.distanceToHome()) && std::isnan(status.flightSeconds()));
        QCOMPARE(status.batteryState(), ui::FlightStatus::BatteryState::Unknown);

        v.setMission({waypoint(56.951, 24.10), waypoint(56.952, 24.10), waypoint(56.953, 24.10)});
        QCOMPARE(status.progressText(), QStringLiteral("3 waypoints on board"));

        // Armed at t=1000, flying to the second waypoint at t=61000, 0.001° north of home.
        report(v, 1000, 56.95, 24.10, {{F::Armed, 1, 1000}});
        report(v, 61000, 56.951, 24.10, {{F::MissionCurrent, 1, 61000}, {F::GroundSpeed, 5, 61000}});
        QTRY_COMPARE(status.activeWaypoint(), 1);
        QCOMPARE(status.progressText(), QStringLiteral("waypoint 2 of 3"));
        QVERIFY(std::abs(status.distanceToHome() - 111.2) < 0.5);
        QVERIFY(std::abs(status.bearingToHome() - 180) < 0.1); // home is due south
        QVERIFY(std::abs(status.bearingToNext()) < 0.1 || std::abs(status.bearingToNext() - 360) < 0.1);
        QVERIFY(std::abs(status.distanceLeft() - 2 * 111.2) < 1);
        QVERIFY(std::abs(status.timeLeft() - 2 * 111.2 / 5) < 0.5);
        QCOMPARE(status.flightSeconds(), 60.0);
        // Two position reports in the last five seconds, 60 s apart: the window holds one; rate unknown.
        QVERIFY(std::isnan(status.telemetryRate()));
        for (int i = 1; i <= 10; ++i)
            report(v, 61000 + i * 100, 56.951, 24.10);
        QTRY_VERIFY(std::abs(status.telemetryRate() - 10) < 0.01);

        // Battery: judged by the level when reported, else by the voltage against the profile's.
        v.ingest({{F::BatteryRemaining, 0.5, 62100}});
        QTRY_COMPARE(status.batteryState(), ui::FlightStatus::BatteryState::Normal);
        v.ingest({{F::BatteryRemaining, 0.2, 62200}});
        QTRY_COMPARE(status.batteryState(), ui::FlightStatus::BatteryState::Low);
        v.ingest({{F::BatteryRemaining, 0.1, 62300}});
        QTRY_COMPARE(status.batteryState(), ui::FlightStatus::BatteryState::Critical);
        using B = ui::FlightStatus::BatteryState;
        QCOMPARE(ui::FlightStatus::judgeBattery(qQNaN(), 14.9, 0.3, 0.15, 14.8, 14.4), B::Normal);
        QCOMPARE(ui::FlightStatus::judgeBattery(qQNaN(), 14.6, 0.3, 0.15, 14.8, 14.4), B::Low);
        QCOMPARE(ui::FlightStatus::judgeBattery(qQNaN(), 14.3, 0.3, 0.15, 14.8, 14.4), B::Critical);
        QCOMPARE(ui::FlightStatus::judgeBattery(qQNaN(), 14.3, 0.3, 0.15, qQNaN(), qQNaN()), B::Unknown);

        // Disarmed: no flight time; past the last waypoint: complete.
        v.ingest({{F::Armed, 0, 62400}, {F::MissionCurrent, 3, 62400}});
        QTRY_VERIFY(std::isnan(status.flightSeconds()));
        QVERIFY(status.missionComplete());
        QCOMPARE(status.progressText(), QStringLiteral("mission complete"));
    }

    void homeIsTheTakeOffPointWhenNotReported()
    {
        vehicle::Vehicle v(nullptr);
        QVERIFY(!ui::FlightStatus::homeOf(v).isValid());
        // An HCI vehicle reports no home: where it was armed is home, also after it landed.
        v.ingest({{F::Latitude, 56.95, 1000}, {F::Longitude, 24.10, 1000}, {F::Armed, 0, 1000}});
        QVERIFY(!ui::FlightStatus::homeOf(v).isValid());
        v.ingest({{F::Latitude, 56.96, 2000}, {F::Longitude, 24.11, 2000}, {F::Armed, 1, 2000}});
        v.ingest({{F::Latitude, 56.97, 3000}, {F::Longitude, 24.12, 3000}, {F::Armed, 1, 3000}});
        v.ingest({{F::Armed, 0, 4000}});
        QGeoCoordinate home = ui::FlightStatus::homeOf(v);
        QVERIFY(std::abs(home.latitude() - 56.96) < 1e-9 && std::abs(home.longitude() - 24.11) < 1e-9);
        // A reported home wins.
        v.ingest({{F::HomeLatitude, 56.9, 5000}, {F::HomeLongitude, 24.0, 5000}});
        home = ui::FlightStatus::homeOf(v);
        QVERIFY(std::abs(home.latitude() - 56.9) < 1e-9 && std::abs(home.longitude() - 24.0) < 1e-9);
    }

    void instrumentsDrawOffscreen()
    {
        test::QuickScene scene(kInstruments, QSize(320, 160));
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *attitude = scene.find<ui::AttitudeIndicator>(QStringLiteral("attitude"));
        auto *compass = scene.find<ui::HeadingCompass>(QStringLiteral("compass"));
        QVERIFY(attitude && compass);
        const QColor sky(0x3f, 0x8f, 0xd8), ground(0x8a, 0x5a, 0x2b), home(0x43, 0xa0, 0x47), next(0xff, 0x8f, 0x00);
        // No attitude yet: neither sky nor ground.
        QImage image = scene.grab();
        QCOMPARE(countNear(image, QRect(10, 10, 140, 140), sky, 20), 0);
        // Level: sky above the middle, ground below.
        attitude->setRoll(0);
        attitude->setPitch(0);
        QTRY_VERIFY(countNear(scene.grab(), QRect(60, 30, 40, 20), sky, 20) > 500);
        image = scene.grab();
        QVERIFY(countNear(image, QRect(60, 110, 40, 20), ground, 20) > 500);
        // Nose up 20°: the horizon drops, ground leaves the band just below the middle.
        attitude->setPitch(20);
        QTRY_VERIFY(countNear(scene.grab(), QRect(60, 95, 40, 10), sky, 20) > 200);
        // Right wing down 30°: the world turns the other way — the horizon's right end rises
        // (ground right of the middle, above it), its left end sinks (sky left, below it).
        attitude->setPitch(0);
        attitude->setRoll(30);
        QTRY_VERIFY(countNear(scene.grab(), QRect(118, 60, 12, 10), ground, 20) > 50);
        QVERIFY(countNear(scene.grab(), QRect(30, 90, 15, 10), sky, 20) > 50);

        // The compass: heading 90°, home due south (180°) shows on the card's right, the next
        // waypoint due north (0°) on its left.
        compass->setHeading(90);
        compass->setBearingToHome(180);
        compass->setBearingToNext(0);
        const QPointF homeAt = compass->markPosition(compass->bearingToHome());
        const QPointF nextAt = compass->markPosition(compass->bearingToNext());
        QVERIFY(homeAt.x() > 120 && std::abs(homeAt.y() - 80) < 2);
        QVERIFY(nextAt.x() < 40 && std::abs(nextAt.y() - 80) < 2);
        const QPoint origin = compass->mapToScene(QPointF(0, 0)).toPoint();
        QTRY_VERIFY(countNear(scene.grab(), QRect(origin + homeAt.toPoint() - QPoint(5, 5), QSize(10, 10)), home) > 10);
        QVERIFY(countNear(scene.grab(), QRect(origin + nextAt.toPoint() - QPoint(4, 4), QSize(8, 8)), next) > 8);
        compass->setBearingToHome(qQNaN());
        QTRY_COMPARE(countNear(scene.grab(), QRect(origin + homeAt.toPoint() - QPoint(5, 5), QSize(10, 10)), home), 0);
    }

    void flightPlanShowsFlownAheadAndActive()
    {
        test::QuickScene scene(kMapScene, QSize(800, 600));
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *layer = scene.find<ui::FlightPlanLayer>(QStringLiteral("plans"));
        QVERIFY(layer);
        vehicle::Vehicle v(nullptr);
        v.setNotifyInterval(0);
        QStandardItemModel fleet;
        fleet.setItemRoleNames({{Qt::UserRole, "vehicle"}});
        auto *row = new QStandardItem;
        row->setData(QVariant::fromValue<QObject *>(&v), Qt::UserRole);
        fleet.appendRow(row);
        layer->setModel(&fleet);
        QCOMPARE(layer->planCount(), 0);
        v.setMission({waypoint(56.950, 24.098), waypoint(56.952, 24.098), waypoint(56.952, 24.104), waypoint(56.950, 24.104)});
        QCOMPARE(layer->planCount(), 1);
        QCOMPARE(layer->waypointCount(0), 4);
        report(v, 1000, 56.952, 24.101, {{F::MissionCurrent, 2, 1000}});
        QTRY_COMPARE(layer->activeWaypoint(0), 2);

        const QColor colour = client::vehicleColor(0), flown(0x9e, 0x9e, 0x9e), ring(0xff, 0xd6, 0x00);
        auto middleOf = [&](int a, int b) { return ((layer->waypointPosition(0, a) + layer->waypointPosition(0, b)) / 2).toPoint(); };
        QTRY_VERIFY(countNear(scene.grab(), QRect(middleOf(2, 3) - QPoint(3, 3), QSize(7, 7)), colour) > 5); // ahead
        QImage image = scene.grab();
        QCOMPARE(countNear(image, QRect(middleOf(0, 1) - QPoint(3, 3), QSize(7, 7)), colour), 0);       // behind: not in colour
        QVERIFY(countNear(image, QRect(middleOf(0, 1) - QPoint(3, 10), QSize(7, 21)), flown) > 2);       // but grey
        const QPoint active = layer->waypointPosition(0, 2).toPoint();
        QVERIFY(countNear(image, QRect(active + QPoint(11, -3), QSize(5, 6)), ring) > 3);                 // ringed

        // The vehicle moves on: the active waypoint advances, the leg it left turns grey.
        report(v, 2000, 56.951, 24.104, {{F::MissionCurrent, 3, 2000}});
        QTRY_COMPARE(layer->activeWaypoint(0), 3);
        QTRY_COMPARE(countNear(scene.grab(), QRect(middleOf(1, 2) - QPoint(3, 3), QSize(7, 7)), colour), 0);
        QVERIFY(countNear(scene.grab(), QRect(layer->waypointPosition(0, 3).toPoint() + QPoint(11, -3), QSize(5, 6)), ring) > 3);
    }

    // A plan is drawn once and shown from its picture while the vehicle moves; a new active
    // waypoint, a new layout (zoom) or a new mission draw it anew, where it now belongs.
    void flightPlanIsKeptAsAPicture()
    {
        test::QuickScene scene(kMapScene, QSize(800, 600));
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *layer = scene.find<ui::FlightPlanLayer>(QStringLiteral("plans"));
        auto *map = scene.find<ui::MapView>(QStringLiteral("map"));
        vehicle::Vehicle v(nullptr);
        v.setNotifyInterval(0);
        QStandardItemModel fleet;
        fleet.setItemRoleNames({{Qt::UserRole, "vehicle"}});
        auto *row = new QStandardItem;
        row->setData(QVariant::fromValue<QObject *>(&v), Qt::UserRole);
        fleet.appendRow(row);
        layer->setModel(&fleet);
        v.setMission({waypoint(56.950, 24.098), waypoint(56.952, 24.098), waypoint(56.952, 24.104), waypoint(56.950, 24.104)});
        report(v, 1000, 56.951, 24.098, {{F::MissionCurrent, 1, 1000}});
        const QColor colour = client::vehicleColor(0);
        auto middleOf = [&](int a, int b) { return ((layer->waypointPosition(0, a) + layer->waypointPosition(0, b)) / 2).toPoint(); };
        auto aheadShown = [&] { return countNear(scene.grab(), QRect(middleOf(2, 3) - QPoint(3, 3), QSize(7, 7)), colour) > 5; };
        QTRY_VERIFY(aheadShown());
        const int drawn = layer->planRedraws(0);
        QVERIFY(drawn >= 1);

        // Moving along the same leg: frames come from the picture.
        for (int i = 1; i <= 5; ++i) {
            report(v, 1000 + 100 * i, 56.951 + 0.0001 * i, 24.098, {{F::MissionCurrent, 1, 1000 + 100 * i}});
            QVERIFY(aheadShown());
        }
        QCOMPARE(layer->planRedraws(0), drawn);

        // The next waypoint: drawn anew once, the leg left behind grey.
        report(v, 2000, 56.952, 24.100, {{F::MissionCurrent, 2, 2000}});
        QTRY_COMPARE(countNear(scene.grab(), QRect(middleOf(0, 1) - QPoint(3, 3), QSize(7, 7)), colour), 0);
        QCOMPARE(layer->planRedraws(0), drawn + 1);

        // Zoomed out: laid out and drawn anew where the waypoints now are.
        const QPointF before = layer->waypointPosition(0, 3);
        map->setZoomLevel(15);
        QTRY_VERIFY((layer->waypointPosition(0, 3) - before).manhattanLength() > 20);
        QTRY_VERIFY(aheadShown());
        QCOMPARE(layer->planRedraws(0), drawn + 2);

        // Another mission: drawn anew.
        v.setMission({waypoint(56.950, 24.100), waypoint(56.951, 24.102), waypoint(56.950, 24.104), waypoint(56.949, 24.106)});
        QTRY_VERIFY(aheadShown());
        QCOMPARE(layer->planRedraws(0), drawn + 3);
    }

    void plotsSeveralFieldsAndSeveralVehicles()
    {
        const QByteArray qml = R"(
import QtQuick
import Sortie.Ui
TelemetryPlot { objectName: "plot"; width: 400; height: 200 }
)";
        test::QuickScene scene(qml, QSize(400, 200));
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *plot = qobject_cast<ui::TelemetryPlot *>(scene.root());
        QVERIFY(plot);
        vehicle::Vehicle a(nullptr), b(nullptr);
        for (int i = 0; i < 20; ++i) {
            a.ingest({{F::AltitudeAgl, 10.0 + i, 1000 + i * 100}, {F::AltitudeAmsl, 30.0 + i, 1000 + i * 100},
                      {F::GroundSpeed, 5.0, 1000 + i * 100}});
            b.ingest({{F::AltitudeAgl, 20.0 - i * 0.5, 1000 + i * 100}});
        }
        // One vehicle, three fields in two units: two axes, three colours.
        plot->setVehicle(&a);
        plot->setFields({QStringLiteral("altitudeAgl"), QStringLiteral("altitudeAmsl"), QStringLiteral("groundSpeed")});
        QSignalSpy plotted(plot, &ui::TelemetryPlot::plotted);
        QTRY_COMPARE(plot->seriesCount(), 3);
        QCOMPARE(plot->axisCount(), 2);
        QCOMPARE(plot->seriesAxis(0), plot->seriesAxis(1)); // metres with metres
        QVERIFY(plot->seriesAxis(2) != plot->seriesAxis(0));
        QVERIFY(plot->seriesColor(0) != plot->seriesColor(1) && plot->seriesColor(1) != plot->seriesColor(2));
        QCOMPARE(plot->sampleCount(), 60);
        // Every vehicle of a fleet, one field: one series each, in the vehicle's map colour.
        QStandardItemModel fleet;
        fleet.setItemRoleNames({{Qt::UserRole, "vehicle"}});
        for (vehicle::Vehicle *v : {&a, &b}) {
            auto *row = new QStandardItem;
            row->setData(QVariant::fromValue<QObject *>(v), Qt::UserRole);
            fleet.appendRow(row);
        }
        plot->setFleet(&fleet);
        plot->setFields({QStringLiteral("altitudeAgl")});
        plot->setCompare(true);
        QTRY_COMPARE(plot->seriesCount(), 2);
        QCOMPARE(plot->axisCount(), 1);
        QCOMPARE(plot->seriesColor(0), client::vehicleColor(0));
        QCOMPARE(plot->seriesColor(1), client::vehicleColor(1));
        QVERIFY(plot->seriesLabel(1).contains(b.name()) || plot->seriesLabel(1).contains(QStringLiteral("altitudeAgl")));
        // Both drawn.
        const QImage image = scene.grab();
        QVERIFY(countNear(image, image.rect(), client::vehicleColor(0), 30) > 30);
        QVERIFY(countNear(image, image.rect(), client::vehicleColor(1), 30) > 30);
    }
};

QTEST_MAIN(TestFlyView)
#include "tst_flyview.moc"
