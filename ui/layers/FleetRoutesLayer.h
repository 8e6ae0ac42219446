#pragma once

#include "MapLayer.h"

#include <QAbstractItemModel>
#include <QColor>
#include <QPointer>
#include <QPolygonF>

#include <vector>

namespace sortie::ui {

// Every route given to a vehicle (the fleet's FleetRoutes, or any list model with its roles:
// `path` a QPolygonF of longitude/latitude, `color`, `state`, `vehicleRow`, `open`), each in its
// vehicle's colour: planned ones lighter, flown ones grey and dashed, the current vehicle's on top
// and bolder. With `hideOpen`, the route open in the editor is left to the editor's own layer. The
// legs and dots are PlanPicture's (the flight plan's look); long paths are simplified first
// (Polyline). Rows are read when the model says they changed, never while drawing; a row whose
// drawn look did not change (a flight's clock ticking) does not redraw the layer.
class FleetRoutesLayer : public MapLayer
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QAbstractItemModel *model READ model WRITE setModel NOTIFY modelChanged)
    // The chosen vehicle's row in the fleet (-1: none): its routes are drawn on top, bolder.
    Q_PROPERTY(int currentVehicleRow READ currentVehicleRow WRITE setCurrentVehicleRow NOTIFY currentVehicleRowChanged)
    Q_PROPERTY(bool hideOpen READ hideOpen WRITE setHideOpen NOTIFY hideOpenChanged)
    Q_PROPERTY(int routeCount READ routeCount NOTIFY routesChanged) // routes drawn

public:
    explicit FleetRoutesLayer(QQuickItem *parent = nullptr);

    QAbstractItemModel *model() const { return m_model; }
    void setModel(QAbstractItemModel *model);
    int currentVehicleRow() const { return m_current; }
    void setCurrentVehicleRow(int row);
    bool hideOpen() const { return m_hideOpen; }
    void setHideOpen(bool hide);
    int routeCount() const;

    // For tests: the row's colour as drawn, and where its path's point `index` is (item pixels).
    Q_INVOKABLE QColor routeColor(int row) const;
    Q_INVOKABLE QPointF pointPosition(int row, int index) const;

    void paint(QPainter *painter) override;

signals:
    void modelChanged();
    void currentVehicleRowChanged();
    void hideOpenChanged();
    void routesChanged();

private:
    struct Route
    {
        QPolygonF path; // x: longitude, y: latitude
        QColor color;
        QString state;
        int vehicleRow = -1;
        bool open = false;
        bool operator==(const Route &) const = default;
    };
    void reload();
    void reloadRows(int first, int last);
    Route read(int row) const;
    bool shown(const Route &route) const;

    QPointer<QAbstractItemModel> m_model;
    std::vector<Route> m_routes;
    int m_current = -1;
    bool m_hideOpen = false;
};

} // namespace sortie::ui
