#pragma once

#include "TileKey.h"

#include <QImage>
#include <QObject>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// Where map tiles come from. A source answers every request later, never inside
// requestTile(), with tileReady or tileFailed. When it cannot reach its tiles at all
// (no network, missing file) it says so through `reachable` and `errorString`; the map then
// shows its offline base map for the tiles it lacks.
class TileSource : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("TileSource is abstract: use XyzTileSource or MbTilesTileSource")
    Q_PROPERTY(QString name READ name WRITE setName NOTIFY infoChanged)
    Q_PROPERTY(QString attribution READ attribution WRITE setAttribution NOTIFY infoChanged)
    Q_PROPERTY(int minimumZoomLevel READ minimumZoomLevel WRITE setMinimumZoomLevel NOTIFY infoChanged)
    Q_PROPERTY(int maximumZoomLevel READ maximumZoomLevel WRITE setMaximumZoomLevel NOTIFY infoChanged)
    Q_PROPERTY(bool reachable READ isReachable NOTIFY reachableChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY reachableChanged)

public:
    explicit TileSource(QObject *parent = nullptr);

    QString name() const { return m_name; }
    QString attribution() const { return m_attribution; }
    int minimumZoomLevel() const { return m_minimumZoom; }
    int maximumZoomLevel() const { return m_maximumZoom; }
    bool isReachable() const { return m_reachable; }
    QString errorString() const { return m_errorString; }
    void setName(const QString &name);
    void setAttribution(const QString &attribution);
    void setMinimumZoomLevel(int zoom);
    void setMaximumZoomLevel(int zoom);

    // Asks for one tile; the answer comes later as tileReady or tileFailed.
    virtual void requestTile(const sortie::ui::TileKey &key) = 0;
    // Forgets queued requests that have not started (the view moved on) and returns them:
    // they will never be answered.
    virtual QList<sortie::ui::TileKey> cancelPending() { return {}; }

signals:
    void tileReady(const sortie::ui::TileKey &key, const QImage &image);
    void tileFailed(const sortie::ui::TileKey &key, const QString &message);
    void infoChanged();
    void reachableChanged();
    // Everything delivered so far is out of date (new file, new template, new colours).
    void invalidated();

protected:
    void setInfo(const QString &name, const QString &attribution, int minimumZoom, int maximumZoom);
    void setReachable(bool reachable, const QString &errorString = {});

private:
    QString m_name;
    QString m_attribution;
    int m_minimumZoom = 0;
    int m_maximumZoom = 19;
    bool m_reachable = true;
    QString m_errorString;
};

} // namespace sortie::ui
