#pragma once

#include "MbTilesFile.h"
#include "TileSource.h"

#include <QList>
#include <QString>

namespace sortie::ui {

// Tiles from an MBTiles file (an SQLite database of raster tiles) for work without a network.
// The file is opened read-only (maptiles::MbTilesFile, the one the prefetch job writes); its
// metadata gives the name, attribution and zoom range.
class MbTilesTileSource : public TileSource
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QString file READ file WRITE setFile NOTIFY fileChanged)
    Q_PROPERTY(bool valid READ isValid NOTIFY fileChanged)

public:
    explicit MbTilesTileSource(QObject *parent = nullptr);
    ~MbTilesTileSource() override;

    QString file() const { return m_file; }
    // Accepts a path or a file:// URL.
    void setFile(const QString &file);
    bool isValid() const { return m_pack.isOpen(); }
    // Opens the same file again (it may have been created or filled since).
    void reopen();

    void requestTile(const TileKey &key) override;
    QList<TileKey> cancelPending() override;

signals:
    void fileChanged();

private:
    void readMetadata();
    void serveQueue();

    QString m_file;
    maptiles::MbTilesFile m_pack;
    QList<TileKey> m_queue;
    bool m_serveScheduled = false;
};

} // namespace sortie::ui
