#pragma once

#include "MapLayer.h"
#include "TrailPicture.h"

#include <QColor>
#include <QHash>
#include <QPolygonF>

#include <deque>
#include <vector>

#include <QAbstractItemModel>

namespace sortie::ui {

// Vehicles over the map from a list model (one row per vehicle): an arrow turned to the
// heading, a label, the home position and a trail of where the vehicle has been, which the
// layer records from the model's position updates. Greyed when the row's stale role is true.
// Labels that would cover one another are stacked below the first, with a leader line; the
// current vehicle is drawn last, ringed, its label on a filled tag.
// The layer also moves its map for the operator: fitToMap() frames every vehicle, centerOn()
// one of them; `follow` keeps the current vehicle in the middle of the map, and `autoFit`
// frames the fleet whenever a vehicle first reports where it is, until the operator moves the map.
// Role names are properties so any vehicle model fits. A move strokes only the trail's new
// piece (TrailPicture); trails are drawn whole again on a new layout, or once the points cut
// from their old ends reach a sixteenth of `trailLength` (until then the picture keeps them).
class VehicleLayer : public MapLayer
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QAbstractItemModel *model READ model WRITE setModel NOTIFY modelChanged)
    Q_PROPERTY(QString idRole MEMBER m_idRole NOTIFY modelChanged)
    Q_PROPERTY(QString latitudeRole MEMBER m_latitudeRole NOTIFY modelChanged)
    Q_PROPERTY(QString longitudeRole MEMBER m_longitudeRole NOTIFY modelChanged)
    Q_PROPERTY(QString headingRole MEMBER m_headingRole NOTIFY modelChanged)
    Q_PROPERTY(QString labelRole MEMBER m_labelRole NOTIFY modelChanged)
    Q_PROPERTY(QString homeLatitudeRole MEMBER m_homeLatitudeRole NOTIFY modelChanged)
    Q_PROPERTY(QString homeLongitudeRole MEMBER m_homeLongitudeRole NOTIFY modelChanged)
    Q_PROPERTY(QString staleRole MEMBER m_staleRole NOTIFY modelChanged)
    Q_PROPERTY(int currentIndex READ currentIndex WRITE setCurrentIndex NOTIFY currentIndexChanged)
    Q_PROPERTY(int trailLength READ trailLength WRITE setTrailLength NOTIFY trailLengthChanged)
    Q_PROPERTY(bool trailsVisible READ trailsVisible WRITE setTrailsVisible NOTIFY trailLengthChanged)
    Q_PROPERTY(int count READ count NOTIFY vehiclesChanged)
    Q_PROPERTY(int positionedCount READ positionedCount NOTIFY vehiclesChanged)
    Q_PROPERTY(bool follow READ follow WRITE setFollow NOTIFY followChanged)
    Q_PROPERTY(bool autoFit READ autoFit WRITE setAutoFit NOTIFY autoFitChanged)

public:
    explicit VehicleLayer(QQuickItem *parent = nullptr);

    QAbstractItemModel *model() const { return m_model; }
    void setModel(QAbstractItemModel *model);
    int currentIndex() const { return m_current; }
    void setCurrentIndex(int row);
    int trailLength() const { return m_trailLength; }
    void setTrailLength(int points);
    bool trailsVisible() const { return m_trailsVisible; }
    void setTrailsVisible(bool visible);
    int count() const { return int(m_vehicles.size()); }
    int positionedCount() const;
    bool follow() const { return m_follow; }
    void setFollow(bool follow);
    bool autoFit() const { return m_autoFit; }
    void setAutoFit(bool on);

    Q_INVOKABLE int vehicleAt(QPointF position, qreal radius = 16) const;
    Q_INVOKABLE int trailPointCount(int row) const;
    Q_INVOKABLE QPointF vehiclePosition(int row) const;
    Q_INVOKABLE void clearTrails();
    // Frames every vehicle that has a position (and its home); false when none has one.
    Q_INVOKABLE bool fitToMap(qreal margin = 60);
    // Moves the map so that the vehicle is in its middle; false when it has no position.
    Q_INVOKABLE bool centerOn(int row);
    // Where the vehicle's label is drawn, in item pixels (empty without a label or position).
    Q_INVOKABLE QRectF labelRect(int row) const;

    void paint(QPainter *painter) override;

signals:
    void modelChanged();
    void currentIndexChanged();
    void trailLengthChanged();
    void vehiclesChanged();
    void vehicleClicked(int row, int modifiers);
    void followChanged();
    void autoFitChanged();

protected:
    void onViewportChanged() override;
    void updatePolish() override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    struct Vehicle
    {
        QString id;
        QString label;
        QPointF position{qQNaN(), qQNaN()}; // normalised
        QPointF home{qQNaN(), qQNaN()};
        double heading = 0;
        bool stale = false;
        QColor color;
    };
    struct Drawn
    {
        QPointF position;
        QPointF home;
        QRectF label;        // in paintViewport pixels
        bool hasPosition = false;
        bool hasHome = false;
        bool labelMoved = false; // stacked away from its vehicle: drawn with a leader line
    };
    struct Trail
    {
        std::deque<QPointF> points; // normalised, oldest first
        qint64 dropped = 0;         // points cut from the front so far
        qint64 drawn = 0;           // points (counted from the first ever) in the picture
    };
    void reload();
    void reloadRows(int first, int last);
    void resolveRoles();
    Vehicle read(int row) const;
    void record(const Vehicle &vehicle);
    void redrawTrails();
    QColor colorOf(const Vehicle &vehicle) const;
    void layOutTrails(const MapViewport &view);
    void layOutLabels();
    void watchMap();
    void onMapMoved();
    void keepCurrentInView();

    QPointer<QAbstractItemModel> m_model;
    QString m_idRole = QStringLiteral("vehicleId");
    QString m_latitudeRole = QStringLiteral("latitude");
    QString m_longitudeRole = QStringLiteral("longitude");
    QString m_headingRole = QStringLiteral("heading");
    QString m_labelRole = QStringLiteral("name");
    QString m_homeLatitudeRole = QStringLiteral("homeLatitude");
    QString m_homeLongitudeRole = QStringLiteral("homeLongitude");
    QString m_staleRole = QStringLiteral("stale");
    QHash<QString, int> m_roles;
    std::vector<Vehicle> m_vehicles;
    QHash<QString, Trail> m_trails; // by vehicle id: survives row moves
    std::vector<Drawn> m_drawn;     // laid out in updatePolish
    TrailPicture m_trailPicture;
    bool m_trailsStale = true;      // the picture must be drawn whole again
    qint64 m_cutSinceRedraw = 0;
    int m_current = -1;
    int m_trailLength = 3000;
    bool m_trailsVisible = true;
    int m_pressRow = -1;
    bool m_follow = false;
    bool m_autoFit = false;
    bool m_movingMap = false;   // the map moves because this layer moved it
    int m_fittedCount = 0;      // vehicles with a position when autoFit last framed them
    QPointer<MapView> m_watchedMap;
    struct Frame
    {
        double latitude = 0, longitude = 0, zoom = -1;
    } m_framed; // where this layer last put the map
};

} // namespace sortie::ui
