#include "DemoScene.h"

#include "Vehicle.h"
#include "VehicleFleet.h"

#include <QQuickWindow>

namespace sortie::app {

namespace {
constexpr int kTelemetryPage = 2; // Main.qml's pages: Login, Mission, Live telemetry
} // namespace

DemoScene::DemoScene(QQuickWindow *window, client::VehicleFleet *fleet, QString vehicleName)
    : QObject(window)
    , m_window(window)
    , m_fleet(fleet)
    , m_vehicleName(std::move(vehicleName))
{
    // The vehicle is listed after the login, and named once its identity arrives.
    connect(m_fleet, &QAbstractItemModel::rowsInserted, this, &DemoScene::follow);
    connect(m_fleet, &QAbstractItemModel::dataChanged, this, &DemoScene::follow);
}

void DemoScene::follow()
{
    for (int row = 0; row < m_fleet->rowCount(); ++row) {
        const vehicle::Vehicle *vehicle = m_fleet->vehicleAt(row);
        if (!vehicle || vehicle->name() != m_vehicleName || !vehicle->position().isValid())
            continue;
        disconnect(m_fleet, nullptr, this, nullptr);
        if (!m_window)
            return;
        m_window->setProperty("currentPage", kTelemetryPage);
        auto *page = m_window->property("telemetryPage").value<QObject *>();
        auto *layer = page ? page->property("vehicleLayer").value<QObject *>() : nullptr;
        if (!layer)
            return;
        layer->setProperty("currentIndex", row);
        layer->setProperty("follow", true);
        return;
    }
}

} // namespace sortie::app
