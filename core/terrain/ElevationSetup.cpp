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
    m_demError.clear();
    if (!demFolder.isEmpty()) {
        if (m_opener) {
            m_tiles = m_opener(demFolder, &m_demError);
        } else {
            auto tiles = std::make_unique<HgtTileSource>(demFolder);
            m_demError = tiles->error();
            if (tiles->isUsable())
                m_tiles = std::move(tiles);
        }
        if (!m_tiles)
            qCWarning(lcTerrain).noquote() << "terrain DEM:" << m_demError;
        else
            qCInfo(lcTerrain).noquote() << "terrain DEM:" << m_tiles->name();
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
