#include "MbTilesTileSource.h"

#include <QFileInfo>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QUrl>
#include <QUuid>

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

MbTilesTileSource::~MbTilesTileSource()
{
    close();
}

void MbTilesTileSource::setFile(const QString &file)
{
    if (file == m_file)
        return;
    m_file = file;
    close();
    const QUrl url(file);
    const QString path = url.isLocalFile() ? url.toLocalFile() : file;
    QString error;
    if (open(path, &error)) {
        readMetadata();
        setReachable(true);
    } else {
        setReachable(false, error);
    }
    emit invalidated();
    emit fileChanged();
}

bool MbTilesTileSource::open(const QString &path, QString *error)
{
    if (path.isEmpty()) {
        *error = tr("No MBTiles file is set.");
        return false;
    }
    if (!QFileInfo(path).isFile()) {
        *error = tr("The MBTiles file %1 does not exist.").arg(path);
        return false;
    }
    const QString name = QStringLiteral("sortie-mbtiles-") + QUuid::createUuid().toString(QUuid::WithoutBraces);
    QString problem;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name);
        db.setDatabaseName(path);
        db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY"));
        if (!db.open()) {
            problem = tr("Cannot open the MBTiles file %1: %2").arg(path, db.lastError().text());
        } else {
            QSqlQuery probe(db);
            if (!probe.exec(QStringLiteral("SELECT zoom_level, tile_column, tile_row, tile_data FROM tiles LIMIT 1")))
                problem = tr("%1 is not an MBTiles file (it has no tiles table).").arg(path);
        }
        if (!problem.isEmpty())
            db.close();
    }
    if (!problem.isEmpty()) {
        QSqlDatabase::removeDatabase(name);
        *error = problem;
        return false;
    }
    m_connection = name;
    return true;
}

void MbTilesTileSource::close()
{
    m_queue.clear();
    if (m_connection.isEmpty())
        return;
    {
        QSqlDatabase db = QSqlDatabase::database(m_connection, false);
        db.close();
    }
    QSqlDatabase::removeDatabase(m_connection);
    m_connection.clear();
}

void MbTilesTileSource::readMetadata()
{
    QSqlQuery query(QSqlDatabase::database(m_connection, false));
    QString title = QFileInfo(m_file).completeBaseName();
    QString attribution;
    int minZoom = 0;
    int maxZoom = 19;
    bool haveMin = false;
    bool haveMax = false;
    if (query.exec(QStringLiteral("SELECT name, value FROM metadata"))) {
        while (query.next()) {
            const QString key = query.value(0).toString();
            const QString value = query.value(1).toString();
            if (key == QLatin1String("name") && !value.isEmpty())
                title = value;
            else if (key == QLatin1String("attribution"))
                attribution = value;
            else if (key == QLatin1String("minzoom"))
                minZoom = value.toInt(&haveMin);
            else if (key == QLatin1String("maxzoom"))
                maxZoom = value.toInt(&haveMax);
        }
    }
    if ((!haveMin || !haveMax)
        && query.exec(QStringLiteral("SELECT MIN(zoom_level), MAX(zoom_level) FROM tiles")) && query.next()
        && !query.value(0).isNull()) {
        if (!haveMin)
            minZoom = query.value(0).toInt();
        if (!haveMax)
            maxZoom = query.value(1).toInt();
    }
    setInfo(title, attribution, minZoom, maxZoom);
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
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    QSqlQuery query(db);
    query.prepare(QStringLiteral("SELECT tile_data FROM tiles WHERE zoom_level = ? AND tile_column = ? AND tile_row = ?"));
    for (int served = 0; served < kTilesPerBatch && !m_queue.isEmpty(); ++served) {
        const TileKey key = m_queue.takeLast();
        query.addBindValue(key.z);
        query.addBindValue(key.x);
        query.addBindValue((1 << key.z) - 1 - key.y);
        if (!query.exec()) {
            emit tileFailed(key, tr("Reading tile %1 failed: %2").arg(key.toString(), query.lastError().text()));
            continue;
        }
        if (!query.next()) {
            emit tileFailed(key, tr("The MBTiles file has no tile %1.").arg(key.toString()));
            continue;
        }
        const QImage image = QImage::fromData(query.value(0).toByteArray());
        if (image.isNull())
            emit tileFailed(key, tr("Tile %1 in the MBTiles file is not a raster image.").arg(key.toString()));
        else
            emit tileReady(key, image.convertToFormat(QImage::Format_ARGB32_Premultiplied));
        query.finish();
    }
    if (!m_queue.isEmpty() && !m_serveScheduled) {
        m_serveScheduled = true;
        QMetaObject::invokeMethod(this, &MbTilesTileSource::serveQueue, Qt::QueuedConnection);
    }
}

} // namespace sortie::ui
