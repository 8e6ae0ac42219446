#include "OrthophotoTiles.h"

#include "OrthophotoRenderer.h"

#include <QLoggingCategory>
#include <QUrl>
#include <QtConcurrent/QtConcurrentRun>

namespace sortie::ui {

namespace {
Q_LOGGING_CATEGORY(lcOrthophoto, "sortie.ui.orthophoto")

QImage renderTile(raster::OrthophotoRenderer &renderer, const TileKey &key)
{
    QString error;
    const raster::RgbaTile tile = renderer.render(key.z, key.x, key.y, 256, &error);
    if (!error.isEmpty())
        qCWarning(lcOrthophoto).noquote() << error;
    if (!tile.covered)
        return {};
    QImage image(tile.rgba.data(), tile.size, tile.size, tile.size * 4, QImage::Format_RGBA8888);
    // Premultiplied: what QPainter blends fastest; the copy detaches from the tile's buffer.
    return image.convertToFormat(QImage::Format_ARGB32_Premultiplied);
}
} // namespace

OrthophotoTiles::OrthophotoTiles(QObject *parent) : QObject(parent)
{
    m_pool.setMaxThreadCount(kWorkers);
}

OrthophotoTiles::~OrthophotoTiles()
{
    m_queue.clear();
    m_pool.waitForDone();  // the workers hold renderers of their own; nothing is delivered after this
}

bool OrthophotoTiles::setFile(const QString &file)
{
    const QString path = file.startsWith(QLatin1String("file:")) ? QUrl(file).toLocalFile() : file;
    if (path == m_file)
        return isOpen() || m_file.isEmpty();
    m_file = path;
    m_error.clear();
    m_renderers.clear();
    m_busy.clear();
    m_queue.clear();
    m_running.clear();
    m_cache.clear();
    m_footprint = {};
    ++m_generation;
    if (!path.isEmpty()) {
        for (int i = 0; i < kWorkers; ++i) {
            std::shared_ptr<raster::OrthophotoRenderer> renderer = raster::OrthophotoRenderer::open(path, &m_error);
            if (!renderer) {
                qCWarning(lcOrthophoto).noquote() << m_error;
                m_renderers.clear();
                break;
            }
            m_renderers.push_back(std::move(renderer));
        }
        m_busy.assign(m_renderers.size(), false);
        if (!m_renderers.empty()) {
            const auto &r = *m_renderers.front();
            m_footprint = QRectF(QPointF(r.west(), r.south()), QPointF(r.east(), r.north()));
        }
    }
    emit fileChanged();
    return isOpen() || path.isEmpty();
}

bool OrthophotoTiles::touches(const TileKey &key) const
{
    return !m_renderers.empty() && m_renderers.front()->touches(key.z, key.x, key.y);
}

void OrthophotoTiles::require(const QList<TileKey> &keys)
{
    m_queue.clear();
    for (const TileKey &key : keys)
        if (touches(key) && !m_cache.contains(key) && !m_running.contains(key))
            m_queue.append(key);
    startNext();
}

void OrthophotoTiles::startNext()
{
    for (size_t worker = 0; worker < m_renderers.size() && !m_queue.isEmpty(); ++worker) {
        if (m_busy[worker])
            continue;
        const TileKey key = m_queue.takeFirst();
        m_busy[worker] = true;
        m_running.insert(key);
        auto *watcher = new QFutureWatcher<QImage>(this);
        const int generation = m_generation;
        connect(watcher, &QFutureWatcher<QImage>::finished, this,
                [this, watcher, key, worker, generation] { finished(watcher, key, int(worker), generation); });
        // The job holds its renderer: a new file may replace it meanwhile.
        std::shared_ptr<raster::OrthophotoRenderer> renderer = m_renderers[worker];
        watcher->setFuture(QtConcurrent::run(&m_pool, [renderer, key] { return renderTile(*renderer, key); }));
    }
}

void OrthophotoTiles::finished(QFutureWatcher<QImage> *watcher, const TileKey &key, int worker, int generation)
{
    const QImage image = watcher->result();
    watcher->deleteLater();
    if (generation != m_generation)
        return;
    m_busy[size_t(worker)] = false;
    m_running.remove(key);
    // An empty image is a tile the picture leaves transparent: cached as such, never asked again.
    m_cache.insert(key, image);
    emit tileReady(key);
    startNext();
}

} // namespace sortie::ui
