#include "ElevationSetup.h"

#include "HciElevationSource.h"
#include "HgtTileSource.h"
#include "NoElevationSource.h"
#include "TerrainLog.h"

namespace sortie::terrain {

ElevationSetup::ElevationSetup(hci::HciSession *session, QObject *parent)
    : QObject(parent)
    , m_server(session ? std::make_unique<HciElevationSource>(session) : nullptr)
    , m_none(std::make_unique<NoElevationSource>())
    , m_rule(std::make_unique<TerrainRule>(&m_service))
{
    configure({});
}

ElevationSetup::~ElevationSetup() = default;

void ElevationSetup::configure(const QString &demFolder, const QStringList &order)
{
    m_tiles.reset();
    if (!demFolder.isEmpty()) {
        m_tiles = std::make_unique<HgtTileSource>(demFolder);
        if (!m_tiles->isUsable()) {
            qCWarning(lcTerrain).noquote() << "terrain tiles:" << m_tiles->error();
            m_tiles.reset();
        } else {
            qCInfo(lcTerrain).noquote() << m_tiles->tileCount() << "SRTM tile(s) in" << demFolder;
        }
    }
    QStringList names = order;
    for (const QString &n : {QStringLiteral("tiles"), QStringLiteral("server")})
        if (!names.contains(n))
            names << n;
    std::vector<ElevationSource *> sources;
    for (const QString &n : names) {
        if (n == QLatin1String("tiles") && m_tiles)
            sources.push_back(m_tiles.get());
        else if (n == QLatin1String("server") && m_server)
            sources.push_back(m_server.get());
    }
    if (sources.empty())
        sources.push_back(m_none.get());
    m_service.setSources(sources);
}

} // namespace sortie::terrain
