#pragma once

#include "CommandPolicy.h"
#include "VehicleChecklist.h"

#include <QObject>
#include <QPointer>

#include <map>

namespace sortie::client {
class FleetRoutes;
class RouteDocument;
class RoutePreparation;
class VehicleFleet;
} // namespace sortie::client

namespace sortie::preflight {

// The pre-flight checklists of the fleet's vehicles, and the gate on the commands they guard
// (handed to the fleet's CommandPolicy): Arm and take-off wait for the items of the Arm gate, Auto
// for those of the Auto gate while the vehicle is on the ground (in the air, Auto resumes a paused
// mission: the pre-flight check is behind it). A vehicle's list is its type's file in `folder`
// (`multicopter.json`), else `default.json` there, else Sortie's own (defaultChecklist()); a file
// with a mistake is not used, and the list says why. The lists are read when a vehicle is first
// checked and again on reload().
//
// The facts come from the vehicle (link, GPS, battery, home, camera), the fleet's routes (the one on
// board and the one planned for it) and the open route's check when it is the vehicle's.
class PreflightChecklists : public QObject, public client::CommandGate
{
    Q_OBJECT
    Q_PROPERTY(QString folder READ folder CONSTANT)
    // Rises with every reload(): a binding that reads it asks checklistFor() again for the new list.
    Q_PROPERTY(int revision READ revision NOTIFY reloaded)

public:
    // `fleet` is required; `routes`, `document` and `preparation` may be null (their items then
    // are missing). None is owned. The gate is handed to the fleet's policy here.
    PreflightChecklists(client::VehicleFleet *fleet, client::FleetRoutes *routes, client::RouteDocument *document,
                        client::RoutePreparation *preparation, QString folder, QObject *parent = nullptr);
    ~PreflightChecklists() override;

    QString folder() const { return m_folder; }
    int revision() const { return m_revision; }

    // The vehicle's list (made on first use, owned here, gone with the vehicle); nullptr for none.
    Q_INVOKABLE sortie::preflight::VehicleChecklist *checklistFor(sortie::vehicle::Vehicle *vehicle);
    // The lists read again from their files; the ticks are lost with the old lists.
    Q_INVOKABLE void reload();

    QStringList blockers(client::CommandPolicy::Command command, const vehicle::Vehicle *vehicle) override;

    // What is known of the vehicle now.
    PreflightFacts factsOf(const vehicle::Vehicle *vehicle) const;

signals:
    void reloaded();

private:
    void refreshAll();

    QPointer<client::VehicleFleet> m_fleet;
    QPointer<client::FleetRoutes> m_routes;
    QPointer<client::RouteDocument> m_document;
    QPointer<client::RoutePreparation> m_preparation;
    QString m_folder;
    int m_revision = 0;
    std::map<const vehicle::Vehicle *, VehicleChecklist *> m_lists;
};

} // namespace sortie::preflight
