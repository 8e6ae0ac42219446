#pragma once

#include "ElevationService.h"
#include "TerrainRule.h"

#include <QStringList>

#include <memory>

namespace sortie::hci {
class HciSession;
}

namespace sortie::terrain {

class HciElevationSource;
class HgtTileSource;
class NoElevationSource;

// The client's terrain: the sources an operator has (a folder of SRTM tiles, the UgCS server the
// client is logged in to), in the order the settings give, behind one ElevationService, plus the
// validation rule that uses it. Source names in `order`: "tiles", "server".
class ElevationSetup : public QObject
{
    Q_OBJECT

public:
    explicit ElevationSetup(hci::HciSession *session, QObject *parent = nullptr);
    ~ElevationSetup() override;

    // An empty folder means no local tiles. The default order is tiles, then server.
    void configure(const QString &demFolder, const QStringList &order = {});
    ElevationService *service() { return &m_service; }
    TerrainRule *rule() { return m_rule.get(); }
    HgtTileSource *tiles() const { return m_tiles.get(); }

private:
    ElevationService m_service;
    std::unique_ptr<HciElevationSource> m_server;
    std::unique_ptr<HgtTileSource> m_tiles;
    std::unique_ptr<NoElevationSource> m_none;
    std::unique_ptr<TerrainRule> m_rule;
};

} // namespace sortie::terrain
