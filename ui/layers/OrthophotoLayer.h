#pragma once

#include "MapLayer.h"
#include "OrthophotoTiles.h"

#include <QList>
#include <QRect>

namespace sortie::ui {

// The operator's orthophoto over the base map (below routes and zones): its Web Mercator tiles,
// rendered off the GUI thread by OrthophotoTiles, drawn where they are ready; while one renders a
// cached ancestor stands in, scaled. Transparent outside the image. Its opacity is the item's.
class OrthophotoLayer : public MapLayer
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QString file READ file WRITE setFile NOTIFY fileChanged)
    Q_PROPERTY(bool valid READ isValid NOTIFY fileChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY fileChanged)
    // Tiles of the image drawn in the last picture, and those still rendering or queued (tests, status).
    Q_PROPERTY(int drawnTiles READ drawnTiles NOTIFY drawn)
    Q_PROPERTY(int pendingTiles READ pendingTiles NOTIFY drawn)

public:
    explicit OrthophotoLayer(QQuickItem *parent = nullptr);

    QString file() const { return m_tiles.file(); }
    void setFile(const QString &file);
    bool isValid() const { return m_tiles.isOpen(); }
    QString errorString() const { return m_tiles.errorString(); }
    int drawnTiles() const { return m_drawnTiles; }
    int pendingTiles() const { return m_tiles.renderingCount() + m_tiles.queuedCount(); }
    // Shows the whole image on the map.
    Q_INVOKABLE void fitToMap(qreal margin = 40);

    void paint(QPainter *painter) override;

signals:
    void fileChanged();
    void drawn();

protected:
    void updatePolish() override;

private:
    struct Placed
    {
        TileKey key;
        QRect target;  // paintViewport pixels
    };
    OrthophotoTiles m_tiles;
    QList<Placed> m_placed;  // laid out in updatePolish
    int m_drawnTiles = 0;
};

} // namespace sortie::ui
