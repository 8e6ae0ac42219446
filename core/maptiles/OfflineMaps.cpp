#include "OfflineMaps.h"

#include "MapTilesLog.h"

#include <QAbstractItemModel>
#include <QCoreApplication>
#include <QFileInfo>
#include <QLocale>
#include <QNetworkAccessManager>
#include <QSettings>
#include <QStandardPaths>

#include <cmath>

namespace sortie::maptiles {

namespace {

QString settingKey(const char *key) { return QStringLiteral("offlineMaps/") + QLatin1String(key); }

int roleOf(const QAbstractItemModel &model, const QByteArray &name)
{
    return model.roleNames().key(name, -1);
}
} // namespace

OfflineMaps::OfflineMaps(QSettings *storage, QObject *parent)
    : QObject(parent)
    , m_storage(storage)
    , m_network(new QNetworkAccessManager(this))
{
    if (m_storage) {
        m_packFile = m_storage->value(settingKey("packFile")).toString();
        m_cacheOnly = m_storage->value(settingKey("cacheOnly"), false).toBool();
        m_attribution = m_storage->value(settingKey("attribution")).toString();
        // A hand-edited value that is not a number in range keeps the default (never 0 by accident).
        const auto number = [this](const char *key, double fallback, double lowest, double highest) {
            bool ok = false;
            const double v = m_storage->value(settingKey(key)).toDouble(&ok);
            return ok && std::isfinite(v) && v >= lowest && v <= highest ? v : fallback;
        };
        m_minZoom = int(number("minZoom", m_minZoom, 0, TileArea::kMaximumZoom));
        m_maxZoom = int(number("maxZoom", m_maxZoom, m_minZoom, TileArea::kMaximumZoom));
        m_margin = number("margin", m_margin, 0, 100000);
        m_limits.maximumConcurrent = int(number("maxConcurrent", m_limits.maximumConcurrent, 1, 64));
        m_limits.maximumTiles = qint64(number("maxTiles", double(m_limits.maximumTiles), 1, 1e9));
        restoreArea();
    }
}

// The last area, so a download cut short by a restart can be resumed as it was: a drawn polygon's
// corners ("lat,lon;lat,lon;…") when there were, else the box ("south,west,north,east").
void OfflineMaps::restoreArea()
{
    const QString polygon = m_storage->value(settingKey("areaCorners")).toString();
    if (!polygon.isEmpty()) {
        QList<QPointF> lonLat;
        for (const QString &corner : polygon.split(QLatin1Char(';'))) {
            const QStringList parts = corner.split(QLatin1Char(','));
            bool okLat = false, okLon = false;
            const double lat = parts.value(0).toDouble(&okLat), lon = parts.value(1).toDouble(&okLon);
            lonLat.append(parts.size() == 2 && okLat && okLon ? QPointF(lon, lat) : QPointF(qQNaN(), qQNaN()));
        }
        const TileArea area = TileArea::polygon(lonLat);
        if (area.isEmpty()) {
            // Not the box instead: that would download another area than the one chosen.
            qCWarning(lcMapTiles) << "The remembered offline area is not usable:" << area.problem();
            return;
        }
        m_area = area;
        m_areaText = m_storage->value(settingKey("areaText")).toString();
        return;
    }
    const QStringList box = m_storage->value(settingKey("area")).toString().split(QLatin1Char(','));
    bool read = box.size() == 4;
    double edge[4] = {};
    for (int i = 0; read && i < 4; ++i)
        edge[i] = box[i].toDouble(&read);
    if (read) {
        const GeoBounds bounds{edge[0], edge[1], edge[2], edge[3]};
        if (bounds.isValid()) {
            m_area = TileArea::rectangle(bounds);
            m_areaText = m_storage->value(settingKey("areaText")).toString();
        }
    }
}

OfflineMaps::~OfflineMaps()
{
    // A running download writes what arrived as it ends; nothing here should hear of it.
    if (m_job)
        m_job->disconnect(this);
}

void OfflineMaps::save(const char *key, const QVariant &value)
{
    if (m_storage)
        m_storage->setValue(settingKey(key), value);
}

void OfflineMaps::setProblem(const QString &problem)
{
    if (problem == m_problem)
        return;
    m_problem = problem;
    emit stateChanged();
}

void OfflineMaps::setUrlTemplate(const QString &urlTemplate)
{
    if (urlTemplate == m_urlTemplate)
        return;
    m_urlTemplate = urlTemplate;
    m_packMeanBytes.reset();
    emit urlTemplateChanged();
    if (m_packFile.isEmpty())
        emit packFileChanged();
    emit estimateChanged();
    emit stateChanged();
}

QString OfflineMaps::packFile() const
{
    if (!m_packFile.isEmpty())
        return m_packFile;
    const QString host = TileUrlTemplate(m_urlTemplate).host();
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/offline-maps/")
        + (host.isEmpty() ? QStringLiteral("tiles") : host) + QStringLiteral(".mbtiles");
}

void OfflineMaps::setPackFile(const QString &file)
{
    if (file == m_packFile)
        return;
    m_packFile = file;
    m_packMeanBytes.reset();
    save("packFile", file);
    emit packFileChanged();
    emit estimateChanged();
}

void OfflineMaps::setCacheOnly(bool cacheOnly)
{
    if (cacheOnly == m_cacheOnly)
        return;
    m_cacheOnly = cacheOnly;
    save("cacheOnly", cacheOnly);
    emit cacheOnlyChanged();
}

void OfflineMaps::setAttribution(const QString &attribution)
{
    if (attribution == m_attribution)
        return;
    m_attribution = attribution;
    save("attribution", attribution);
    emit attributionChanged();
}

void OfflineMaps::setMinimumZoom(int zoom)
{
    zoom = std::clamp(zoom, 0, TileArea::kMaximumZoom);
    if (zoom == m_minZoom)
        return;
    m_minZoom = zoom;
    save("minZoom", zoom);
    emit estimateChanged();
    emit stateChanged();
}

void OfflineMaps::setMaximumZoom(int zoom)
{
    zoom = std::clamp(zoom, 0, TileArea::kMaximumZoom);
    if (zoom == m_maxZoom)
        return;
    m_maxZoom = zoom;
    save("maxZoom", zoom);
    emit estimateChanged();
    emit stateChanged();
}

void OfflineMaps::setMarginMetres(double metres)
{
    if (!std::isfinite(metres) || metres < 0 || metres == m_margin)
        return;
    m_margin = metres;
    save("margin", metres);
    emit estimateChanged();
}

bool OfflineMaps::useRouteArea(QAbstractItemModel *route)
{
    if (!route) {
        setProblem(tr("No route is open."));
        return false;
    }
    const int latRole = roleOf(*route, "latitude"), lonRole = roleOf(*route, "longitude"), polygonRole = roleOf(*route, "polygon");
    GeoBounds box{90, 180, -90, -180};
    int points = 0;
    const auto add = [&](const QVariant &lat, const QVariant &lon) {
        bool okLat = false, okLon = false;
        const double la = lat.toDouble(&okLat), lo = lon.toDouble(&okLon);
        if (!okLat || !okLon || !std::isfinite(la) || !std::isfinite(lo) || std::abs(la) > 90 || std::abs(lo) > 180)
            return;
        box = {std::min(box.south, la), std::min(box.west, lo), std::max(box.north, la), std::max(box.east, lo)};
        ++points;
    };
    for (int row = 0; row < route->rowCount(); ++row) {
        const QModelIndex index = route->index(row, 0);
        if (latRole >= 0 && lonRole >= 0)
            add(index.data(latRole), index.data(lonRole));
        if (polygonRole >= 0) {
            const QVariantList corners = index.data(polygonRole).toList();
            for (const QVariant &corner : corners) {
                const QVariantMap map = corner.toMap();
                add(map.value(QStringLiteral("latitude")), map.value(QStringLiteral("longitude")));
            }
        }
    }
    if (points == 0) {
        setProblem(tr("The open route has no waypoints to take the area from."));
        return false;
    }
    const GeoBounds grown = box.grown(m_margin);
    if (!grown.isValid()) {
        setProblem(tr("The route is a single point: give a margin around it."));
        return false;
    }
    setArea(TileArea::rectangle(grown), QCoreApplication::translate("sortie::maptiles::OfflineMaps", "The open route (%n point(s)) and %1 m around it", nullptr, points).arg(m_margin));
    return true;
}

bool OfflineMaps::useViewArea(const QGeoCoordinate &southWest, const QGeoCoordinate &northEast)
{
    const GeoBounds bounds{std::max(southWest.latitude(), -TileArea::kMaximumLatitude), southWest.longitude(),
                           std::min(northEast.latitude(), TileArea::kMaximumLatitude), northEast.longitude()};
    if (!southWest.isValid() || !northEast.isValid() || !bounds.isValid()) {
        setProblem(tr("The map's view is not an area (%1 to %2).").arg(southWest.toString(), northEast.toString()));
        return false;
    }
    setArea(TileArea::rectangle(bounds), tr("The map's view"));
    return true;
}

bool OfflineMaps::usePolygonArea(const QVariantList &corners)
{
    QList<QPointF> lonLat;
    for (const QVariant &corner : corners) {
        QGeoCoordinate c = corner.value<QGeoCoordinate>();
        if (corner.metaType() != QMetaType::fromType<QGeoCoordinate>()) {
            const QVariantMap map = corner.toMap();
            bool okLat = false, okLon = false;
            c = QGeoCoordinate(map.value(QStringLiteral("latitude")).toDouble(&okLat), map.value(QStringLiteral("longitude")).toDouble(&okLon));
            if (!okLat || !okLon)
                c = {};
        }
        // An unreadable corner stays in the list, so the problem names it by its place.
        lonLat.append(c.isValid() ? QPointF(c.longitude(), c.latitude()) : QPointF(qQNaN(), qQNaN()));
    }
    const TileArea area = TileArea::polygon(lonLat);
    if (area.isEmpty()) {
        setProblem(tr("The drawn area cannot be used: %1").arg(area.problem()));
        return false;
    }
    setArea(area, tr("A drawn area (%n corner(s))", nullptr, int(lonLat.size())));
    return true;
}

bool OfflineMaps::useRectangleArea(const QGeoCoordinate &corner, const QGeoCoordinate &opposite)
{
    const GeoBounds bounds{std::max(std::min(corner.latitude(), opposite.latitude()), -TileArea::kMaximumLatitude),
                           std::min(corner.longitude(), opposite.longitude()),
                           std::min(std::max(corner.latitude(), opposite.latitude()), TileArea::kMaximumLatitude),
                           std::max(corner.longitude(), opposite.longitude())};
    if (!corner.isValid() || !opposite.isValid() || !bounds.isValid()) {
        setProblem(tr("The drawn rectangle is not an area (%1 to %2).").arg(corner.toString(), opposite.toString()));
        return false;
    }
    setArea(TileArea::rectangle(bounds), tr("A drawn rectangle"));
    return true;
}

QVariantList OfflineMaps::areaCorners() const
{
    QVariantList out;
    for (const QPointF &c : m_area.corners())
        out.append(QVariant::fromValue(QGeoCoordinate(c.y(), c.x())));
    return out;
}

void OfflineMaps::setArea(const TileArea &area, const QString &description)
{
    m_area = area;
    m_areaText = description;
    const GeoBounds b = area.bounds();
    save("area", QStringLiteral("%1,%2,%3,%4").arg(b.south, 0, 'g', 12).arg(b.west, 0, 'g', 12).arg(b.north, 0, 'g', 12).arg(b.east, 0, 'g', 12));
    QStringList corners;
    if (!area.isRectangle()) {
        for (const QPointF &c : area.corners())
            corners.append(QStringLiteral("%1,%2").arg(c.y(), 0, 'g', 12).arg(c.x(), 0, 'g', 12));
    }
    if (corners.isEmpty() && m_storage)
        m_storage->remove(settingKey("areaCorners"));
    else
        save("areaCorners", corners.join(QLatin1Char(';')));
    save("areaText", description);
    setProblem({});
    emit estimateChanged();
    emit stateChanged();
}

double OfflineMaps::tileCount() const
{
    if (m_area.isEmpty() || m_minZoom > m_maxZoom)
        return -1;
    return double(m_area.tileCount(m_minZoom, m_maxZoom));
}

double OfflineMaps::estimatedBytes() const
{
    const double count = tileCount();
    if (count < 0)
        return -1;
    if (!m_packMeanBytes && QFileInfo(packFile()).isFile()) {
        MbTilesFile pack;
        if (pack.open(packFile(), MbTilesFile::Mode::ReadOnly, nullptr))
            const_cast<OfflineMaps *>(this)->m_packMeanBytes = pack.meanTileBytes();
    }
    return count * m_packMeanBytes.value_or(kAssumedTileBytes);
}

QString OfflineMaps::estimateText() const
{
    const double count = tileCount();
    if (count < 0)
        return m_minZoom > m_maxZoom ? tr("The lowest zoom is above the highest.") : tr("Choose an area.");
    const QLocale locale;
    QString text = tr("%1 tiles, about %2").arg(locale.toString(qint64(count)), locale.formattedDataSize(qint64(estimatedBytes())));
    text += m_packMeanBytes ? tr(" (at this pack's mean of %1 a tile)").arg(locale.formattedDataSize(qint64(*m_packMeanBytes)))
                            : tr(" (assuming %1 a tile)").arg(locale.formattedDataSize(qint64(kAssumedTileBytes)));
    if (count > m_limits.maximumTiles)
        text += tr(": more than the limit of %1 tiles, choose a smaller area or fewer zoom levels").arg(locale.toString(m_limits.maximumTiles));
    return text;
}

bool OfflineMaps::canStart() const
{
    const double count = tileCount();
    return !running() && TileUrlTemplate(m_urlTemplate).isUsable() && count > 0 && count <= m_limits.maximumTiles;
}

bool OfflineMaps::running() const
{
    return m_job && (m_job->state() == TilePrefetch::State::Running || m_job->state() == TilePrefetch::State::Paused);
}

bool OfflineMaps::paused() const
{
    return m_job && m_job->state() == TilePrefetch::State::Paused;
}

void OfflineMaps::start()
{
    if (running())
        return;
    const QString serverProblem = TileUrlTemplate::validate(m_urlTemplate);
    if (!serverProblem.isEmpty()) {
        setProblem(tr("Choose a web tile server in Map source first: %1").arg(serverProblem));
        return;
    }
    PrefetchPlan plan{TileUrlTemplate(m_urlTemplate), m_area, m_minZoom, m_maxZoom, packFile(), {}, m_attribution};
    m_job = std::make_unique<TilePrefetch>(m_network, std::move(plan), m_limits);
    connect(m_job.get(), &TilePrefetch::progressChanged, this, &OfflineMaps::progressChanged);
    connect(m_job.get(), &TilePrefetch::stateChanged, this, [this] {
        if (m_job->state() == TilePrefetch::State::Failed)
            m_problem = m_job->problem();
        emit stateChanged();
    });
    connect(m_job.get(), &TilePrefetch::finished, this, [this] {
        m_packMeanBytes.reset(); // the pack's own tiles now say what a tile weighs
        emit estimateChanged();
    });
    setProblem({});
    m_job->start();
    emit stateChanged();
    emit progressChanged();
}

void OfflineMaps::pause()
{
    if (m_job)
        m_job->pause();
}

void OfflineMaps::resume()
{
    if (m_job && m_job->state() == TilePrefetch::State::Paused)
        m_job->resume();
    else
        start(); // after a restart: tiles already in the pack are skipped
}

void OfflineMaps::stop()
{
    if (m_job)
        m_job->stop();
}

double OfflineMaps::progress() const
{
    if (!m_job || m_job->total() <= 0)
        return 0;
    return double(m_job->done()) / double(m_job->total());
}

QString OfflineMaps::progressText() const
{
    if (!m_job || m_job->state() == TilePrefetch::State::Idle)
        return {};
    const QLocale locale;
    QString text = tr("%1 of %2 tiles").arg(locale.toString(m_job->done()), locale.toString(m_job->total()));
    if (m_job->skipped() > 0)
        text += tr(" · %1 already in the pack").arg(locale.toString(m_job->skipped()));
    if (m_job->failed() > 0)
        text += tr(" · %1 not stored").arg(locale.toString(m_job->failed()));
    switch (m_job->state()) {
    case TilePrefetch::State::Paused: text += tr(" · paused"); break;
    case TilePrefetch::State::Finished: text += tr(" · done"); break;
    case TilePrefetch::State::Stopped: text += tr(" · stopped"); break;
    case TilePrefetch::State::Failed: text += tr(" · failed"); break;
    default: break;
    }
    return text;
}

QStringList OfflineMaps::failures() const
{
    return m_job ? m_job->failures() : QStringList{};
}

} // namespace sortie::maptiles
