#pragma once

#include "MapView.h"
#include "ScaleBarLength.h"

#include <QPointer>
#include <QQuickPaintedItem>

namespace sortie::ui {

// A scale bar for a MapView, measured at the map's centre latitude.
class MapScaleBar : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(sortie::ui::MapView *map READ map WRITE setMap NOTIFY mapChanged)
    Q_PROPERTY(bool imperial READ isImperial WRITE setImperial NOTIFY scaleChanged)
    Q_PROPERTY(QString label READ label NOTIFY scaleChanged)
    Q_PROPERTY(double barWidth READ barWidth NOTIFY scaleChanged)
    Q_PROPERTY(QColor color READ color WRITE setColor NOTIFY colorChanged)

public:
    explicit MapScaleBar(QQuickItem *parent = nullptr);

    MapView *map() const { return m_map; }
    void setMap(MapView *map);
    bool isImperial() const { return m_imperial; }
    void setImperial(bool imperial);
    QString label() const { return m_length.label; }
    double barWidth() const { return m_length.pixels; }
    QColor color() const { return m_color; }
    void setColor(const QColor &color);

    void paint(QPainter *painter) override;

signals:
    void mapChanged();
    void scaleChanged();
    void colorChanged();

protected:
    void geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry) override;

private:
    void recompute();

    QPointer<MapView> m_map;
    bool m_imperial = false;
    QColor m_color = Qt::black;
    ScaleBarLength m_length;
};

} // namespace sortie::ui
