#include "MbTilesTileSource.h"

#include <QFileInfo>
#include <QLoggingCategory>
#include <QUrl>

Q_LOGGING_CATEGORY(lcMbTiles, "sortie.ui.mbtiles")

namespace sortie::ui {

namespace {
constexpr int kTilesPerBatch = 16; // keeps the UI thread responsive while a screenful loads
}

MbTilesTileSource::MbTilesTileSource(QObject *parent)
    : TileSource(parent)
{
    setInfo(tr("MBTiles"), {}, 0, 19);
    setReachable(false, tr("No MBTiles file is set."));
}

MbTilesTileSource::~MbTilesTileSource() = default;

void MbTilesTileSource::setFile(const QString &file)
{
    if (file == m_file)
        return;
    m_file = file;
    reopen();
    emit fileChanged();
}

void MbTilesTileSource::reopen()
{
    m_queue.clear();
    const QUrl url(m_file);
    const QString path = url.isLocalFile() ? url.toLocalFile() : m_file;
    QString error;
    if (m_pack.open(path, maptiles::MbTilesFile::Mode::ReadOnly, &error)) {
        readMetadata();
        setReachable(true);
    } else {
        setReachable(false, error);
    }
    emit invalidated();
}

void MbTilesTileSource::readMetadata()
{
    const maptiles::MbTilesMetadata meta = m_pack.metadata();
    for (const QString &problem : meta.problems)
        qCWarning(lcMbTiles) << m_pack.path() << "metadata:" << problem;
    const QString title = meta.name.isEmpty() ? QFileInfo(m_pack.path()).completeBaseName() : meta.name;
    int minZoom = meta.minZoom.value_or(0);
    int maxZoom = meta.maxZoom.value_or(19);
    if (!meta.minZoom || !meta.maxZoom) {
        if (const auto stored = m_pack.storedZoomRange()) {
            minZoom = meta.minZoom.value_or(stored->first);
            maxZoom = meta.maxZoom.value_or(stored->second);
        }
    }
    setInfo(title, meta.attribution, minZoom, maxZoom);
}

void MbTilesTileSource::requestTile(const TileKey &key)
{
    m_queue.removeAll(key);
    m_queue.append(key);
    if (!m_serveScheduled) {
        m_serveScheduled = true;
        QMetaObject::invokeMethod(this, &MbTilesTileSource::serveQueue, Qt::QueuedConnection);
    }
}

QList<TileKey> MbTilesTileSource::cancelPending()
{
    QList<TileKey> cancelled;
    cancelled.swap(m_queue);
    return cancelled;
}

void MbTilesTileSource::serveQueue()
{
    m_serveScheduled = false;
    if (!isValid()) {
        const QList<TileKey> failed = cancelPending();
        for (const TileKey &key : failed)
            emit tileFailed(key, errorString());
        return;
    }
    for (int served = 0; served < kTilesPerBatch && !m_queue.isEmpty(); ++served) {
        const TileKey key = m_queue.takeLast();
        QString error;
        const std::optional<QByteArray> bytes = m_pack.tile({key.z, key.x, key.y}, &error);
        if (!bytes) {
            emit tileFailed(key, error.isEmpty() ? tr("The MBTiles file has no tile %1.").arg(key.toString()) : error);
            continue;
        }
        const QImage image = QImage::fromData(*bytes);
        if (image.isNull())
            emit tileFailed(key, tr("Tile %1 in the MBTiles file is not a raster image.").arg(key.toString()));
        else
            emit tileReady(key, image.convertToFormat(QImage::Format_ARGB32_Premultiplied));
    }
    if (!m_queue.isEmpty() && !m_serveScheduled) {
        m_serveScheduled = true;
        QMetaObject::invokeMethod(this, &MbTilesTileSource::serveQueue, Qt::QueuedConnection);
    }
}

} // namespace sortie::ui
