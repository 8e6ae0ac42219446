// What the fly view costs per frame, offscreen with the software scene graph at 1280x800: 20
// vehicles flying 50-waypoint missions under them (FlightPlanLayer) with their arrows, labels and
// trails (VehicleLayer), every vehicle reporting every frame; then 200 vehicles on one spot (the
// label stacking at its worst); and FlightStatus deriving progress, home, flight time and rate
// per telemetry notification. Prints ms per frame (wall and the GUI thread's CPU) and the load average.
#include "BenchClock.h"
#include "FlightPlanLayer.h"
#include "FlightStatus.h"
#include "QuickScene.h"
#include "Vehicle.h"
#include "VehicleLayer.h"

#include <QElapsedTimer>
#include <QGuiApplication>
#include <QStandardItemModel>
#include <QtQml/qqmlextensionplugin.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;
using vehicle::TelemetryField;

namespace {

const QByteArray kScene = R"(
import QtQuick
import Sortie.Ui
Item {
    MapView { id: map; objectName: "map"; anchors.fill: parent; latitude: 56.95; longitude: 24.1; zoomLevel: 13 }
    FlightPlanLayer { objectName: "plans"; anchors.fill: parent; map: map; currentIndex: 0 }
    VehicleLayer { objectName: "vehicles"; anchors.fill: parent; map: map; currentIndex: 0 }
}
)";

enum Role { VehicleRole = Qt::UserRole + 1, IdRole, NameRole, LatRole, LonRole, HeadingRole };

struct Fleet
{
    QStandardItemModel model;
    std::vector<std::unique_ptr<vehicle::Vehicle>> vehicles;
    int tick = 0;
    bool together = false;

    Fleet(int count, bool oneSpot)
        : together(oneSpot)
    {
        model.setItemRoleNames({{VehicleRole, "vehicle"}, {IdRole, "vehicleId"}, {NameRole, "name"}, {LatRole, "latitude"},
                                {LonRole, "longitude"}, {HeadingRole, "heading"}});
        for (int i = 0; i < count; ++i) {
            auto v = std::make_unique<vehicle::Vehicle>(nullptr);
            v->setNotifyInterval(0);
            std::vector<vehicle::MissionItem> mission;
            for (int w = 0; w < 50; ++w) // a lawnmower of 50 waypoints around the vehicle's own patch
                mission.push_back({(56.93 + (i % 5) * 0.01 + (w / 2) * 0.0004),
                                   (24.05 + (i / 5) * 0.02 + ((w / 2 + w) % 2) * 0.008), 40, 8, 0, {}});
            v->setMission(std::move(mission));
            auto *item = new QStandardItem;
            item->setData(QVariant::fromValue<QObject *>(v.get()), VehicleRole);
            item->setData(QStringLiteral("v%1").arg(i), IdRole);
            item->setData(QStringLiteral("EMU-%1").arg(101 + i), NameRole);
            model.appendRow(item);
            vehicles.push_back(std::move(v));
        }
        move();
    }

    void move()
    {
        ++tick;
        for (int i = 0; i < int(vehicles.size()); ++i) {
            const double a = (tick + i * 7) * 0.02;
            const double lat = together ? 56.95 : 56.93 + (i % 5) * 0.01 + 0.004 * std::sin(a);
            const double lon = together ? 24.10 : 24.05 + (i / 5) * 0.02 + 0.006 * std::cos(a);
            const int64_t t = 1000 + tick * 100;
            vehicles[size_t(i)]->ingest({{TelemetryField::Latitude, lat, t}, {TelemetryField::Longitude, lon, t},
                                         {TelemetryField::MissionCurrent, double((tick / 20) % 50), t},
                                         {TelemetryField::Armed, 1, t}, {TelemetryField::GroundSpeed, 8, t}});
            QStandardItem *item = model.item(i);
            item->setData(lat, LatRole);
            item->setData(lon, LonRole);
            item->setData(std::fmod(a * 57.3, 360.0), HeadingRole);
        }
    }
};

void run(const char *name, int vehicles, bool oneSpot, int frames)
{
    test::QuickScene scene(kScene, QSize(1280, 800));
    if (!scene.isReady()) {
        std::fprintf(stderr, "scene failed: %s\n", qPrintable(scene.errors()));
        return;
    }
    Fleet fleet(vehicles, oneSpot);
    auto *plans = scene.find<ui::FlightPlanLayer>(QStringLiteral("plans"));
    plans->setModel(&fleet.model);
    auto redraws = [&] {
        int n = 0;
        for (int row = 0; row < vehicles; ++row)
            n += plans->planRedraws(row);
        return n;
    };
    scene.find<ui::VehicleLayer>(QStringLiteral("vehicles"))->setModel(&fleet.model);
    for (int i = 0; i < 5; ++i) { // warm up
        fleet.move();
        QCoreApplication::processEvents();
        scene.grab();
    }
    QElapsedTimer clock;
    clock.start();
    const double cpuStart = test::threadCpuMs();
    const int redrawsBefore = redraws();
    for (int i = 0; i < frames; ++i) {
        fleet.move();
        QCoreApplication::processEvents(); // the vehicles' notifications
        scene.grab();
    }
    const double wall = double(clock.nsecsElapsed()) / 1e6 / frames;
    const double cpu = (test::threadCpuMs() - cpuStart) / frames;
    const double redrawn = double(redraws() - redrawsBefore) / frames;
    std::printf("%-52s %10.2f %13.2f %14.1f\n", name, wall, cpu, redrawn);
}

void statusCost(int notifications)
{
    Fleet fleet(1, false);
    ui::FlightStatus status;
    status.setVehicle(fleet.vehicles.front().get());
    for (int i = 0; i < 3000; ++i) // five minutes of history at 10 Hz
        fleet.move();
    const double cpuStart = test::threadCpuMs();
    for (int i = 0; i < notifications; ++i)
        status.refresh();
    const double us = (test::threadCpuMs() - cpuStart) * 1e3 / notifications;
    std::printf("%-52s %10s %13.1f (µs)\n", "FlightStatus::refresh, 50 waypoints, 5 min of history", "", us);
}

} // namespace

int main(int argc, char **argv)
{
    test::useSoftwareRendering();
    QGuiApplication app(argc, argv);
    const int frames = argc > 1 ? std::max(10, std::atoi(argv[1])) : 200;
    std::printf("bench_flyview: %d frames per case, 1280x800, software scene graph, load average %.1f\n", frames, test::loadAverage());
    std::printf("%-52s %10s %13s %14s\n", "case", "ms/frame", "cpu ms/frame", "plans redrawn");
    run("20 vehicles flying 50-waypoint missions, all reporting", 20, false, frames);
    run("200 on one spot, 50-waypoint missions, labels stacked", 200, true, frames / 4);
    statusCost(20000);
    std::printf("load average at the end: %.1f\n", test::loadAverage());
    return 0;
}
