#pragma once

#include "TileCache.h"
#include "TileKey.h"

#include <QFutureWatcher>
#include <QImage>
#include <QList>
#include <QObject>
#include <QSet>
#include <QThreadPool>

#include <memory>
#include <vector>

namespace sortie::raster {
class OrthophotoRenderer;
}

namespace sortie::ui {

// An orthophoto's Web Mercator tiles for the map, rendered off the GUI thread: the tiles the map
// asks for (nearest the middle first) are warped by core/raster's OrthophotoRenderer on a small
// thread pool, one renderer (one GDAL dataset) per worker, and kept in a bounded cache. A newer
// request replaces the queue of tiles not yet started, so a pan never waits for tiles it left.
class OrthophotoTiles : public QObject
{
    Q_OBJECT

public:
    static constexpr int kWorkers = 2;

    explicit OrthophotoTiles(QObject *parent = nullptr);
    ~OrthophotoTiles() override;

    // Opens the image (a path or a file:// URL; empty: none). False, with errorString() naming the
    // file and GDAL's reason, when it cannot be drawn.
    bool setFile(const QString &file);
    QString file() const { return m_file; }
    bool isOpen() const { return !m_renderers.empty(); }
    QString errorString() const { return m_error; }
    // The image's WGS-84 box (degrees): south, west, north, east; all 0 when none is open.
    QRectF footprint() const { return m_footprint; }

    bool touches(const TileKey &key) const;
    const QImage *find(const TileKey &key) const { return m_cache.find(key); }
    // The tiles wanted now: those neither cached nor under way are rendered, in this order.
    void require(const QList<TileKey> &keys);
    int renderingCount() const { return int(m_running.size()); }
    int queuedCount() const { return int(m_queue.size()); }

signals:
    void tileReady(const sortie::ui::TileKey &key);
    void fileChanged();

private:
    void startNext();
    void finished(QFutureWatcher<QImage> *watcher, const TileKey &key, int worker, int generation);

    QString m_file;
    QString m_error;
    QRectF m_footprint;
    std::vector<std::shared_ptr<raster::OrthophotoRenderer>> m_renderers;  // one per worker
    std::vector<bool> m_busy;
    QThreadPool m_pool;
    TileCache m_cache{96};
    QList<TileKey> m_queue;
    QSet<TileKey> m_running;
    int m_generation = 0;  // a new file: answers for the old one are dropped
};

} // namespace sortie::ui
