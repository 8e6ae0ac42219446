#pragma once

#include "ElevationService.h"
#include "TerrainRule.h"

#include <QStringList>

#include <functional>
#include <memory>

namespace sortie::hci {
class HciSession;
}

namespace sortie::terrain {

class HciElevationSource;
class HgtTileSource;
class NoElevationSource;

// The client's terrain: the sources an operator has (a DEM file or folder, the UgCS server the
// client is logged in to), in the order the settings give, behind one ElevationService, plus the
// validation rule that uses it. Source names in `order`: "tiles", "server". The local DEM is opened
// by the opener the owner gives (ClientGraph gives core/raster's, which reads any GDAL raster);
// without one, by HgtTileSource (SRTM .hgt only): core/terrain sits below core/raster.
class ElevationSetup : public QObject
{
    Q_OBJECT

public:
    explicit ElevationSetup(hci::HciSession *session, QObject *parent = nullptr);
    ~ElevationSetup() override;

    // Opens a DEM path as one source; null with the reason (naming the file) when it is unusable.
    using DemOpener = std::function<std::unique_ptr<ElevationSource>(const QString &path, QString *error)>;
    void setDemOpener(DemOpener opener) { m_opener = std::move(opener); }

    // An empty path means no local DEM. The default order is tiles, then server.
    void configure(const QString &demFolder, const QStringList &order = {});
    ElevationService *service() { return &m_service; }
    TerrainRule *rule() { return m_rule.get(); }
    ElevationSource *tiles() const { return m_tiles.get(); }
    // Why the last configured DEM path is not used (empty when it is, or none was given).
    QString demError() const { return m_demError; }

private:
    ElevationService m_service;
    std::unique_ptr<HciElevationSource> m_server;
    DemOpener m_opener;
    std::unique_ptr<ElevationSource> m_tiles;
    QString m_demError;
    std::unique_ptr<NoElevationSource> m_none;
    std::unique_ptr<TerrainRule> m_rule;
};

} // namespace sortie::terrain
