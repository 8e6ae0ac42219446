#pragma once

#include "LayerCanvas.h"
#include "MapLayer.h"
#include "ModelCoordinates.h"
#include "RouteFrame.h"
#include "RoutePainter.h"

#include <QGeoCoordinate>
#include <QItemSelectionModel>

namespace sortie::ui {

// A route over the map: legs and numbered waypoints from any list model with latitude and
// longitude roles (the mission RouteModel, or a CoordinateListModel), the selection of a
// QItemSelectionModel highlighted. With `editable`, a press on a waypoint selects it (Ctrl
// toggles, Shift extends) and a drag moves it, or the whole selection when it is selected;
// the layer only previews the move and reports it with waypointsMoved: whoever owns the model
// applies it (as an undoable command). A click on a leg reports legClicked. Everything else
// goes through to the map. With `actionMarksRole`, a role of flags (1: camera, 2: other actions),
// labelled waypoints carry a badge saying they have actions.
class RouteLayer : public MapLayer
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QAbstractItemModel *model READ model WRITE setModel NOTIFY modelChanged)
    Q_PROPERTY(QString latitudeRole READ latitudeRole WRITE setLatitudeRole NOTIFY modelChanged)
    Q_PROPERTY(QString longitudeRole READ longitudeRole WRITE setLongitudeRole NOTIFY modelChanged)
    Q_PROPERTY(QString actionMarksRole READ actionMarksRole WRITE setActionMarksRole NOTIFY modelChanged) // "": none
    Q_PROPERTY(QItemSelectionModel *selectionModel READ selectionModel WRITE setSelectionModel NOTIFY selectionModelChanged)
    Q_PROPERTY(bool editable READ isEditable WRITE setEditable NOTIFY editableChanged)
    Q_PROPERTY(QColor color READ color WRITE setColor NOTIFY colorChanged)
    Q_PROPERTY(bool dragging READ isDragging NOTIFY draggingChanged)
    Q_PROPERTY(int count READ count NOTIFY frameChanged)
    Q_PROPERTY(int visibleWaypointCount READ visibleWaypointCount NOTIFY frameChanged)
    Q_PROPERTY(int labelledWaypointCount READ labelledWaypointCount NOTIFY frameChanged)

public:
    explicit RouteLayer(QQuickItem *parent = nullptr);

    QAbstractItemModel *model() const { return m_points.model(); }
    void setModel(QAbstractItemModel *model);
    QString latitudeRole() const { return QString::fromUtf8(m_points.latitudeRole()); }
    void setLatitudeRole(const QString &role);
    QString longitudeRole() const { return QString::fromUtf8(m_points.longitudeRole()); }
    void setLongitudeRole(const QString &role);
    QString actionMarksRole() const { return QString::fromUtf8(m_marksRole); }
    void setActionMarksRole(const QString &role);
    QItemSelectionModel *selectionModel() const { return m_selection; }
    void setSelectionModel(QItemSelectionModel *selection);
    bool isEditable() const { return m_editable; }
    void setEditable(bool editable);
    QColor color() const { return m_style.leg; }
    void setColor(const QColor &color);
    bool isDragging() const { return m_dragging; }
    int count() const { return m_points.count(); }
    int visibleWaypointCount() const { return m_frame.visibleWaypoints; }
    int labelledWaypointCount() const { return m_frame.labelledWaypoints; }

    // Hit testing in item pixels. The waypoint nearest `position` within `radius`, or -1.
    Q_INVOKABLE int waypointAt(QPointF position, qreal radius = 12) const;
    // The leg (from waypoint i to i + 1, as i) within `tolerance` of `position`, or -1.
    Q_INVOKABLE int legAt(QPointF position, qreal tolerance = 6) const;
    Q_INVOKABLE QList<int> waypointsIn(const QRectF &rect) const;
    // Rubber-band selection: replaces the selection, or adds to it with Ctrl.
    Q_INVOKABLE void selectInRect(const QRectF &rect, int modifiers);
    Q_INVOKABLE QPointF waypointPosition(int row) const;
    Q_INVOKABLE void fitToMap(qreal margin = 40);

    void paint(QPainter *painter) override;

signals:
    void modelChanged();
    void selectionModelChanged();
    void editableChanged();
    void colorChanged();
    void draggingChanged();
    void frameChanged();
    void waypointClicked(int row, int modifiers);
    void legClicked(int leg, const QGeoCoordinate &coordinate, int modifiers);
    // A drag ended: rows and their new positions, in the same order (RouteEditor::moveWaypoints).
    void waypointsMoved(const QList<int> &rows, const QList<QGeoCoordinate> &coordinates);

protected:
    void onViewportChanged() override;
    void updatePolish() override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseUngrabEvent() override;

private:
    void pointsChanged(int first, int last);
    void reloadMarks(int first, int last);
    void reloadSelection();
    void pressWaypoint(int row, Qt::KeyboardModifiers modifiers);
    void setDragging(bool dragging);
    QPointF normalisedAt(QPointF screen) const;
    void placeOverlay();

    ModelCoordinates m_points;
    QPointer<QItemSelectionModel> m_selection;
    std::vector<bool> m_selected;
    QByteArray m_marksRole;
    std::vector<quint8> m_marks;  // per row, RouteModel::ActionMark flags
    int m_current = -1;
    bool m_editable = false;
    RoutePainter::Style m_style;
    RoutePainter m_painter;
    LayerCanvas *m_overlay = nullptr; // the moving part of a drag, over the still picture
    RouteFrame m_frame;
    bool m_frameStale = true; // more than the drag offset changed since the last build

    int m_pressRow = -1;
    int m_pressLeg = -1;
    QPointF m_pressPos;
    Qt::KeyboardModifiers m_pressModifiers;
    bool m_dragging = false;
    std::vector<int> m_dragRows;
    QPointF m_dragOffset;
};

} // namespace sortie::ui
