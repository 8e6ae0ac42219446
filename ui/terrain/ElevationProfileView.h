#pragma once

#include "TerrainProfileModel.h"
#include "Theme.h"

#include <QColor>
#include <QItemSelectionModel>
#include <QPointer>
#include <QVariant>
#include <QQuickPaintedItem>
#include <QtQml/qqmlregistration.h>

#include <vector>

namespace sortie::endurance {
class RouteEndurance;
}

namespace sortie::ui {

// The elevation profile under the map: the ground along the route (filled), the route's altitude,
// the clearance band (ground + safe distance), stretches flown too low in red, stretches without
// terrain data hatched, the source named, the selected waypoints marked. Hovering shows distance,
// ground, altitude and clearance; clicking selects the leg's first waypoint in `selectionModel`.
// Paints a per-pixel-column summary, so a profile of 100,000 samples costs what its width costs.
class ElevationProfileView : public QQuickPaintedItem
{
    Q_OBJECT
    Q_MOC_INCLUDE("RouteEndurance.h")
    QML_ELEMENT
    Q_PROPERTY(sortie::ui::TerrainProfileModel *model READ model WRITE setModel NOTIFY modelChanged)
    Q_PROPERTY(QItemSelectionModel *selectionModel READ selectionModel WRITE setSelectionModel NOTIFY selectionModelChanged)
    Q_PROPERTY(QString readout READ readout NOTIFY readoutChanged)  // the hovered point, empty when none
    Q_PROPERTY(int hoveredLeg READ hoveredLeg NOTIFY readoutChanged)
    // Its ground, words and marks (the light scheme's without one).
    Q_PROPERTY(sortie::ui::Theme *theme READ theme WRITE setTheme NOTIFY colorsChanged)
    // The route's endurance: its battery changes and point of no return are marked along the
    // profile, each a vertical line at its distance along the flown path, with its name.
    Q_PROPERTY(sortie::endurance::RouteEndurance *endurance READ endurance WRITE setEndurance NOTIFY enduranceChanged)
    Q_PROPERTY(int markerCount READ markerCount NOTIFY markersChanged)
    // The words painted above the plot, on the right: the lowest clearance (or the hovered point).
    // Read-only, so that what is painted can be read (a language change re-words it).
    Q_PROPERTY(QString headline READ headline NOTIFY headlineChanged)

public:
    Theme *theme() const { return m_theme; }
    void setTheme(Theme *theme);
    explicit ElevationProfileView(QQuickItem *parent = nullptr);

    TerrainProfileModel *model() const { return m_model; }
    void setModel(TerrainProfileModel *model);
    QItemSelectionModel *selectionModel() const { return m_selection; }
    endurance::RouteEndurance *endurance() const;
    void setEndurance(endurance::RouteEndurance *endurance);
    int markerCount() const { return int(m_markers.size()); }
    void setSelectionModel(QItemSelectionModel *selection);
    QString readout() const { return m_readout; }
    int hoveredLeg() const { return m_hoveredLeg; }
    QString headline() const;

    // Where a distance along the route is drawn, and back (item coordinates).
    Q_INVOKABLE double xOf(double distance) const;
    Q_INVOKABLE double distanceAt(double x) const;
    Q_INVOKABLE double yOf(double altitude) const;
    // Where the plot is drawn (item coordinates), for overlays that draw in its axes.
    Q_INVOKABLE QRectF plotArea() const { return plotRect(); }
    // The leg under x, -1 outside the plot.
    Q_INVOKABLE int legAt(double x) const;
    // Hover and click as the mouse does them (also for tests and keyboard users).
    Q_INVOKABLE void hoverAt(double x);
    Q_INVOKABLE void clickAt(double x);
    // The distance along the path where marker `index` is drawn; NaN when it is not.
    Q_INVOKABLE double markerDistance(int index) const;

    void paint(QPainter *painter) override;

signals:
    void modelChanged();
    void selectionModelChanged();
    void readoutChanged();
    void colorsChanged();
    void enduranceChanged();
    void markersChanged();
    void headlineChanged();
    // A click on a leg: its index (0-based) and the route row it starts at.
    void legClicked(int leg, int row);

protected:
    void hoverMoveEvent(QHoverEvent *event) override;
    void hoverLeaveEvent(QHoverEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry) override;

private:
    // A place marked along the profile, from the endurance estimate.
    enum class MarkerKind { PlannedChange, UnplannedChange, NoReturn };
    struct Marker
    {
        double distance;  // metres along the flown path
        MarkerKind kind;
    };
    void readMarkers();
    void rescale();
    QRectF plotRect() const;

    QPointer<TerrainProfileModel> m_model;
    QPointer<endurance::RouteEndurance> m_endurance;
    std::vector<Marker> m_markers;
    QPointer<QItemSelectionModel> m_selection;
    QString m_readout;
    int m_hoveredLeg = -1;
    double m_hoverX = -1;
    double m_low = 0, m_high = 100;  // the altitude axis, metres
    QPointer<Theme> m_theme;
};

} // namespace sortie::ui
