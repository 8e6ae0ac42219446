#pragma once

#include <QObject>
#include <QPointer>
#include <QString>

class QQuickWindow;

namespace sortie::client {
class VehicleFleet;
} // namespace sortie::client

namespace sortie::app {

// --demo-scene flying: once the demo's flying vehicle is in the fleet, shows the live telemetry
// page with that vehicle chosen and followed, as an operator would after a click on the vehicle
// and on Follow (the benchmark's second scene, docs/performance.md).
class DemoScene : public QObject
{
    Q_OBJECT

public:
    DemoScene(QQuickWindow *window, client::VehicleFleet *fleet, QString vehicleName);

private:
    void follow();

    QPointer<QQuickWindow> m_window;
    client::VehicleFleet *m_fleet;
    QString m_vehicleName;
};

} // namespace sortie::app
