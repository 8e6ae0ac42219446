#pragma once

#include "MapLayer.h"
#include "CoordinateListModel.h"
#include "MissionEnums.h"
#include "ModelCoordinates.h"

#include <QColor>
#include <QGeoCoordinate>
#include <QPolygonF>

namespace sortie::ui {

// An area-scan segment over the map: the survey polygon (filled, with vertex handles) and the
// transects the planner generated inside it, each from a list model with latitude and longitude
// roles. `transectModel` rows are the scan path in flight order. With `editable`, dragging a
// vertex reports vertexMoved at every step (EditStep Continuing) and at the drop (Done), so the
// owner can apply it live and see the path follow; a click on an edge reports edgeClicked (to
// insert a vertex) and a right click on a vertex vertexRemoveRequested. The layer previews the
// drag itself until the owner's model catches up.
class AreaScanLayer : public MapLayer
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QAbstractItemModel *polygonModel READ polygonModel WRITE setPolygonModel NOTIFY modelsChanged)
    Q_PROPERTY(QAbstractItemModel *transectModel READ transectModel WRITE setTransectModel NOTIFY modelsChanged)
    // Instead of models: lists of QGeoCoordinates (what RouteDocument gives for its current scan).
    Q_PROPERTY(QVariantList polygon READ polygon WRITE setPolygon NOTIFY modelsChanged)
    Q_PROPERTY(QVariantList path READ path WRITE setPath NOTIFY modelsChanged)
    Q_PROPERTY(bool editable READ isEditable WRITE setEditable NOTIFY editableChanged)
    Q_PROPERTY(QColor color READ color WRITE setColor NOTIFY colorChanged)
    Q_PROPERTY(int vertexCount READ vertexCount NOTIFY modelsChanged)
    // false: the points are a line (a corridor's centre line), not an area: no fill, no closing edge.
    Q_PROPERTY(bool closed READ isClosed WRITE setClosed NOTIFY shapeChanged)
    // A circle around the first point, metres (0: none), with a handle on its east side to drag.
    Q_PROPERTY(double radius READ radius WRITE setRadius NOTIFY shapeChanged)
    Q_PROPERTY(int transectPointCount READ transectPointCount NOTIFY modelsChanged)

public:
    explicit AreaScanLayer(QQuickItem *parent = nullptr);

    QAbstractItemModel *polygonModel() const { return m_polygon.model(); }
    void setPolygonModel(QAbstractItemModel *model);
    QAbstractItemModel *transectModel() const { return m_transects.model(); }
    void setTransectModel(QAbstractItemModel *model);
    QVariantList polygon() const { return m_polygonList; }
    void setPolygon(const QVariantList &coordinates);
    QVariantList path() const { return m_pathList; }
    void setPath(const QVariantList &coordinates);
    bool isEditable() const { return m_editable; }
    void setEditable(bool editable);
    QColor color() const { return m_color; }
    void setColor(const QColor &color);
    int vertexCount() const { return m_polygon.count(); }
    bool isClosed() const { return m_closed; }
    void setClosed(bool closed);
    double radius() const { return m_radius; }
    void setRadius(double meters);
    // Where the radius handle is, in item pixels (NaN when there is no circle).
    Q_INVOKABLE QPointF radiusHandlePosition() const;
    int transectPointCount() const { return m_transects.count(); }

    Q_INVOKABLE int vertexAt(QPointF position, qreal radius = 10) const;
    Q_INVOKABLE int edgeAt(QPointF position, qreal tolerance = 6) const;

    void paint(QPainter *painter) override;

signals:
    void modelsChanged();
    void editableChanged();
    void colorChanged();
    void vertexMoved(int index, const QGeoCoordinate &coordinate, sortie::mission::MissionEnums::EditStep step);
    void vertexRemoveRequested(int index);
    void radiusMoved(double meters, sortie::mission::MissionEnums::EditStep step);
    void shapeChanged();
    // The edge from vertex index to the next one (the last edge closes the polygon).
    void edgeClicked(int index, const QGeoCoordinate &coordinate, int modifiers);

protected:
    void updatePolish() override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseUngrabEvent() override;

private:
    QGeoCoordinate dragTarget() const;
    double metersPerUnit() const;  // ground metres per normalised unit at the circle's centre
    double radiusAt(QPointF position) const;
    static QPolygonF project(const std::vector<QPointF> &points, int displaced, QPointF offset, const MapViewport &view);

    CoordinateListModel m_ownPolygon; // behind the list properties
    CoordinateListModel m_ownPath;
    QVariantList m_polygonList;
    QVariantList m_pathList;
    ModelCoordinates m_polygon;
    ModelCoordinates m_transects;
    bool m_editable = false;
    QColor m_color{0x43, 0xa0, 0x47};
    QPolygonF m_drawnPolygon;   // laid out in updatePolish
    QPolygonF m_drawnTransects;
    int m_pressVertex = -1;
    int m_pressEdge = -1;
    QPointF m_pressPos;
    QPointF m_pressPoint;  // the pressed vertex where the drag began (normalised)
    bool m_pressRadius = false;
    bool m_closed = true;
    double m_radius = 0.0;
    double m_dragRadius = 0.0;  // what the handle shows while dragged
    QPointF m_dragOffset;
    bool m_dragging = false;
};

} // namespace sortie::ui
