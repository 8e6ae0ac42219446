#pragma once

#include "TileArea.h"
#include "TilePrefetch.h"

#include <QGeoCoordinate>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QVariant>

#include <memory>

class QAbstractItemModel;
class QNetworkAccessManager;
class QSettings;

namespace sortie::maptiles {

// What the operator's "Offline maps" dialog binds to: the area (the open route's bounds plus a
// margin, the map's view, or a polygon or rectangle drawn on the map), the zoom range, the tile count and size before starting, the
// download (start, pause, resume, stop; progress; what could not be stored), the pack it fills,
// and whether the map reads that pack only (cache-only: the network is never used). The choices
// are kept in the settings, so a download interrupted by a restart resumes where it was.
class OfflineMaps : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QString urlTemplate READ urlTemplate WRITE setUrlTemplate NOTIFY urlTemplateChanged)
    Q_PROPERTY(QString packFile READ packFile WRITE setPackFile NOTIFY packFileChanged)
    Q_PROPERTY(bool cacheOnly READ cacheOnly WRITE setCacheOnly NOTIFY cacheOnlyChanged)
    Q_PROPERTY(QString attribution READ attribution WRITE setAttribution NOTIFY attributionChanged)
    Q_PROPERTY(int minimumZoom READ minimumZoom WRITE setMinimumZoom NOTIFY estimateChanged)
    Q_PROPERTY(int maximumZoom READ maximumZoom WRITE setMaximumZoom NOTIFY estimateChanged)
    Q_PROPERTY(double marginMetres READ marginMetres WRITE setMarginMetres NOTIFY estimateChanged)
    Q_PROPERTY(QString areaText READ areaText NOTIFY estimateChanged)
    Q_PROPERTY(QVariantList areaCorners READ areaCorners NOTIFY estimateChanged)
    Q_PROPERTY(double tileCount READ tileCount NOTIFY estimateChanged)
    Q_PROPERTY(double estimatedBytes READ estimatedBytes NOTIFY estimateChanged)
    Q_PROPERTY(QString estimateText READ estimateText NOTIFY estimateChanged)
    Q_PROPERTY(bool canStart READ canStart NOTIFY stateChanged)
    Q_PROPERTY(bool running READ running NOTIFY stateChanged)
    Q_PROPERTY(bool paused READ paused NOTIFY stateChanged)
    Q_PROPERTY(double progress READ progress NOTIFY progressChanged)
    Q_PROPERTY(QString progressText READ progressText NOTIFY progressChanged)
    Q_PROPERTY(QStringList failures READ failures NOTIFY progressChanged)
    Q_PROPERTY(QString problem READ problem NOTIFY stateChanged)

public:
    // `storage` (not owned) keeps the choices; null keeps them for this run only.
    explicit OfflineMaps(QSettings *storage, QObject *parent = nullptr);
    ~OfflineMaps() override;

    QString urlTemplate() const { return m_urlTemplate; }
    void setUrlTemplate(const QString &urlTemplate);
    // The chosen pack, else one per tile server under the application's data folder.
    QString packFile() const;
    void setPackFile(const QString &file);
    bool cacheOnly() const { return m_cacheOnly; }
    void setCacheOnly(bool cacheOnly);
    QString attribution() const { return m_attribution; }
    void setAttribution(const QString &attribution);
    int minimumZoom() const { return m_minZoom; }
    void setMinimumZoom(int zoom);
    int maximumZoom() const { return m_maxZoom; }
    void setMaximumZoom(int zoom);
    double marginMetres() const { return m_margin; }
    void setMarginMetres(double metres);
    PrefetchLimits &limits() { return m_limits; }

    // The area: the route's extent (a model with `latitude`/`longitude` roles, and `polygon`
    // lists of {latitude, longitude} for area segments) grown by the margin, or the map's view.
    Q_INVOKABLE bool useRouteArea(QAbstractItemModel *route);
    Q_INVOKABLE bool useViewArea(const QGeoCoordinate &southWest, const QGeoCoordinate &northEast);
    // A polygon drawn on the map: corners as QGeoCoordinate or {latitude, longitude}. An unusable
    // one (fewer than three corners, edges crossing, across the antimeridian) sets `problem` and
    // keeps the area there was.
    Q_INVOKABLE bool usePolygonArea(const QVariantList &corners);
    // A rectangle dragged on the map: any two opposite corners.
    Q_INVOKABLE bool useRectangleArea(const QGeoCoordinate &corner, const QGeoCoordinate &opposite);
    void setArea(const TileArea &area, const QString &description);
    const TileArea &area() const { return m_area; }

    QString areaText() const { return m_areaText; }
    // The area's corners (QGeoCoordinate), for drawing it on the map; empty without an area.
    QVariantList areaCorners() const;
    double tileCount() const;      // -1: no area yet
    double estimatedBytes() const; // -1: no area yet
    QString estimateText() const;

    Q_INVOKABLE void start();
    Q_INVOKABLE void pause();
    Q_INVOKABLE void resume();
    Q_INVOKABLE void stop();
    bool canStart() const;
    bool running() const;
    bool paused() const;
    double progress() const;
    QString progressText() const;
    QStringList failures() const;
    QString problem() const { return m_problem; }
    const TilePrefetch *job() const { return m_job.get(); }

    // Bytes a tile is assumed to take before the pack holds any (then its own mean is used).
    static constexpr double kAssumedTileBytes = 20000;

signals:
    void urlTemplateChanged();
    void packFileChanged();
    void cacheOnlyChanged();
    void attributionChanged();
    void estimateChanged();
    void stateChanged();
    void progressChanged();

private:
    void save(const char *key, const QVariant &value);
    void setProblem(const QString &problem);
    void restoreArea();

    QSettings *m_storage;
    QNetworkAccessManager *m_network;
    QString m_urlTemplate;
    QString m_packFile;
    bool m_cacheOnly = false;
    QString m_attribution;
    int m_minZoom = 10;
    int m_maxZoom = 16;
    double m_margin = 500;
    TileArea m_area;
    QString m_areaText;
    std::optional<double> m_packMeanBytes;
    PrefetchLimits m_limits;
    std::unique_ptr<TilePrefetch> m_job;
    QString m_problem;
};

} // namespace sortie::maptiles
