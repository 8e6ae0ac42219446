#include "SettingsWiring.h"

#include "AppSettings.h"
#include "ClientGraph.h"
#include "ConnectionController.h"

#include <QObject>

namespace sortie::ui {

SettingsWiring::SettingsWiring(client::ClientGraph &graph, AppSettings &settings)
{
    // The graph read the setting (or --dem) at start; only a choice made since then re-opens the terrain.
    m_terrain = QObject::connect(&settings, &AppSettings::demPathChanged, &graph,
                                 [&graph, &settings, chosen = settings.demPath()]() mutable {
        if (settings.demPath() == chosen)
            return;
        chosen = settings.demPath();
        graph.useDem(chosen);
    });
    m_password = QObject::connect(&graph.connection(), &client::ConnectionController::ready, &settings,
                                  &AppSettings::loginSucceeded);
}

SettingsWiring::~SettingsWiring()
{
    QObject::disconnect(m_terrain);
    QObject::disconnect(m_password);
}

// i18n: not text below (a diagnostic for the log and the tests, as ClientGraph::wiring())
QStringList SettingsWiring::wiring() const
{
    return {QStringLiteral("terrain setting: %1").arg(m_terrain ? QStringLiteral("the DEM chosen in the map source dialog") : QStringLiteral("read at start only")),
            QStringLiteral("password: %1").arg(m_password ? QStringLiteral("remembered once the server accepted it") : QStringLiteral("never remembered"))};
}

} // namespace sortie::ui
