#pragma once

#include <QMetaObject>
#include <QStringList>

namespace sortie::client {
class ClientGraph;
}

namespace sortie::ui {

class AppSettings;

// What of the operator's settings the client follows, wired in one place for the program and every
// UI fixture (ui::MainWindow makes it): the terrain reads the DEM chosen in the map source dialog
// (a --dem given at start stands until the operator picks another), and a password is remembered
// only once the server accepted it. Here rather than in the graph because the settings are the
// shell's and core/ below knows none of them.
class SettingsWiring
{
public:
    // Both must outlive this object.
    SettingsWiring(client::ClientGraph &graph, AppSettings &settings);
    ~SettingsWiring();
    SettingsWiring(const SettingsWiring &) = delete;
    SettingsWiring &operator=(const SettingsWiring &) = delete;

    // One line per connection made, read back from the connections themselves (as
    // ClientGraph::wiring() does): a test compares a fixture's with the program's.
    QStringList wiring() const;

private:
    QMetaObject::Connection m_terrain;
    QMetaObject::Connection m_password;
};

} // namespace sortie::ui
