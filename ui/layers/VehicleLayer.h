#pragma once

#include "MapLayer.h"
#include "VehicleCamera.h"
#include "VehicleMark.h"
#include "VehicleModelReader.h"
#include "VehicleTrails.h"

#include <QAbstractItemModel>

#include <vector>

namespace sortie::ui {

// Vehicles over the map from a list model (one row per vehicle): an arrow turned to the
// heading, a label, the home position and a trail of where the vehicle has been. Greyed when
// the row's stale role is true; the current vehicle is drawn last, ringed, its label on a
// filled tag. Role names are properties so any vehicle model fits.
// The layer keeps the rows (VehicleModelReader) and hands the work out: VehicleTrails records
// and strokes the trails, LabelPlacer keeps the labels apart, VehiclePainter draws a vehicle,
// and VehicleCamera moves the map (fitToMap, centerOn, `follow`, `autoFit`).
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
    int trailLength() const { return m_trails.length(); }
    void setTrailLength(int points);
    bool trailsVisible() const { return m_trails.isVisible(); }
    void setTrailsVisible(bool visible);
    int count() const { return int(m_vehicles.size()); }
    int positionedCount() const;
    bool follow() const { return m_camera.follow(); }
    void setFollow(bool follow) { m_camera.setFollow(follow); }
    bool autoFit() const { return m_camera.autoFit(); }
    void setAutoFit(bool on) { m_camera.setAutoFit(on); }

    Q_INVOKABLE int vehicleAt(QPointF position, qreal radius = 16) const;
    Q_INVOKABLE int trailPointCount(int row) const;
    Q_INVOKABLE QPointF vehiclePosition(int row) const;
    Q_INVOKABLE void clearTrails();
    // Frames every vehicle that has a position (and its home); false when none has one.
    Q_INVOKABLE bool fitToMap(qreal margin = 60) { return m_camera.fitAll(margin); }
    // Moves the map so that the vehicle is in its middle; false when it has no position.
    Q_INVOKABLE bool centerOn(int row) { return m_camera.centerOn(row); }
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
    // Where a vehicle is drawn, in paintViewport pixels: laid out in updatePolish.
    struct Drawn
    {
        QPointF position;
        QPointF home;
        QRectF label;
        bool hasPosition = false;
        bool hasHome = false;
        bool labelMoved = false; // stacked away from its vehicle: drawn with a leader line
    };
    void reload();
    void reloadRows(int first, int last);
    void layOutLabels();
    void redraw();

    QPointer<QAbstractItemModel> m_model;
    QString m_idRole = VehicleRoleNames().id;
    QString m_latitudeRole = VehicleRoleNames().latitude;
    QString m_longitudeRole = VehicleRoleNames().longitude;
    QString m_headingRole = VehicleRoleNames().heading;
    QString m_labelRole = VehicleRoleNames().label;
    QString m_homeLatitudeRole = VehicleRoleNames().homeLatitude;
    QString m_homeLongitudeRole = VehicleRoleNames().homeLongitude;
    QString m_staleRole = VehicleRoleNames().stale;
    VehicleModelReader m_reader;
    std::vector<VehicleMark> m_vehicles;
    std::vector<Drawn> m_drawn;
    VehicleTrails m_trails;
    VehicleCamera m_camera{m_vehicles};
    int m_current = -1;
    int m_pressRow = -1;
};

} // namespace sortie::ui
