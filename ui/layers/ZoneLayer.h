#pragma once

#include "MapLayer.h"

#include <QColor>
#include <QGeoCoordinate>
#include <QPainterPath>
#include <QPointer>

#include <vector>

namespace sortie::airspace {
class Airspace;
}

namespace sortie::ui {

// The store's zones over the map: exclusion zones hatched red, inclusion zones outlined green,
// zones switched off (or that cannot be checked) dashed grey, the chosen one with a halo; each
// labelled with its name and floor – ceiling where the label fits (LabelPlacer; a label that would
// overlap another is left out, never drawn over it). Hovering a zone shows its source and limits
// (`hoverText`, for a ToolTip; from the map's cursor). Only drawn: clicks and hover go on to the map.
class ZoneLayer : public MapLayer
{
    Q_OBJECT
    Q_MOC_INCLUDE("Airspace.h")
    QML_ELEMENT
    Q_PROPERTY(sortie::airspace::Airspace *airspace READ airspace WRITE setAirspace NOTIFY airspaceChanged)
    Q_PROPERTY(int labelCount READ labelCount NOTIFY drawn)
    Q_PROPERTY(QString hoverText READ hoverText NOTIFY hoverChanged)      // empty when no zone is under the mouse
    Q_PROPERTY(QPointF hoverPosition READ hoverPosition NOTIFY hoverChanged)

public:
    explicit ZoneLayer(QQuickItem *parent = nullptr);

    airspace::Airspace *airspace() const { return m_airspace; }
    void setAirspace(airspace::Airspace *airspace);
    int labelCount() const { return int(m_labels.size()); }
    QString hoverText() const { return m_hoverText; }
    QPointF hoverPosition() const { return m_hoverPosition; }

    // The zone (store row) drawn under a point of this item, the topmost; -1 for none.
    Q_INVOKABLE int zoneAt(QPointF position) const;
    // What the tooltip says about a zone: name, kind, source and origin, floor and ceiling.
    Q_INVOKABLE QString describe(int row) const;
    // Where a zone's label is anchored (its middle), in this item's coordinates; NaN when not drawn.
    Q_INVOKABLE QPointF zoneCentre(int row) const;
    // Drawn labels, in this item's coordinates, and the row each is for (tests).
    Q_INVOKABLE QRectF labelRect(int index) const;
    Q_INVOKABLE int labelZone(int index) const;
    // Hover as the mouse does it (also for tests).
    Q_INVOKABLE void hoverAt(QPointF position);

    void paint(QPainter *painter) override;
    std::vector<QRectF> placedLabels() const override;

protected:
    void onViewportChanged() override;

signals:
    void airspaceChanged();
    void hoverChanged();
    void drawn();

private:
    // A zone's outline in longitude/latitude: polygons with holes, or the circle(s) as rings.
    struct Outline
    {
        std::vector<std::vector<QGeoCoordinate>> rings;  // closed by the painter
        std::vector<bool> hole;
        QGeoCoordinate centre;  // where the label is anchored
        QRectF box;             // longitude (x) and latitude (y) extent: what is off screen is not drawn
    };
    struct Label
    {
        int row;
        QRectF rect;  // paint coordinates
    };
    void readZones();
    void followCursor();
    QPainterPath pathOf(const Outline &outline, const MapViewport &view, QPointF offset = {}) const;
    static QRectF screenBox(const Outline &outline, const MapViewport &view);

    QPointer<airspace::Airspace> m_airspace;
    std::vector<Outline> m_outlines;  // by row
    std::vector<Label> m_labels;
    QString m_hoverText;
    QPointF m_hoverPosition;
    QMetaObject::Connection m_cursorConnection;
};

} // namespace sortie::ui
